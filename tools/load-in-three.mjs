// Loads a .glb with three.js's GLTFLoader in Node and reports what three.js sees, so tests can
// prove our exports work in a real glTF consumer, not only in our own reader.
// Usage: node tools/load-in-three.mjs FILE.glb
// Prints one JSON object: meshes, skinnedMeshes, bones, morphTargets (names from
// morphTargetDictionary), animations [{name, duration, tracks}], and when there is an animation,
// `playback`: the first clip played by an AnimationMixer to half its duration, with how many bones
// moved from the bind pose and the largest rotation change (radians) / translation change (metres).
// Exit status 1 when loading fails, 2 for a usage error.
import { readFile } from 'node:fs/promises';
import { AnimationMixer } from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';

const path = process.argv[2];
if (!path) {
  console.error('usage: node load-in-three.mjs FILE.glb');
  process.exit(2);
}

function parse(bytes) {
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  return new Promise((resolve, reject) => new GLTFLoader().parse(buffer, '', resolve, reject));
}

try {
  const gltf = await parse(await readFile(path));
  const scene = gltf.scene;
  let meshes = 0;
  let skinnedMeshes = 0;
  const morphTargets = new Set();
  const bones = [];
  scene.traverse((o) => {
    if (o.isMesh) meshes++;
    if (o.isSkinnedMesh) skinnedMeshes++;
    if (o.isBone) bones.push(o);
    for (const name of Object.keys(o.morphTargetDictionary ?? {})) morphTargets.add(name);
  });
  const report = {
    file: path,
    meshes,
    skinnedMeshes,
    bones: bones.length,
    morphTargets: [...morphTargets],
    animations: gltf.animations.map((a) => ({ name: a.name, duration: a.duration, tracks: a.tracks.length })),
  };
  if (gltf.animations.length > 0) {
    const bind = bones.map((b) => ({ q: b.quaternion.clone(), p: b.position.clone() }));
    const mixer = new AnimationMixer(scene);
    const clip = gltf.animations[0];
    mixer.clipAction(clip).play();
    mixer.update(clip.duration / 2);
    let moved = 0;
    let maxAngle = 0;
    let maxShift = 0;
    bones.forEach((b, i) => {
      const angle = b.quaternion.angleTo(bind[i].q);
      const shift = b.position.distanceTo(bind[i].p);
      if (angle > 1e-4 || shift > 1e-5) moved++;
      maxAngle = Math.max(maxAngle, angle);
      maxShift = Math.max(maxShift, shift);
    });
    report.playback = { clip: clip.name, time: clip.duration / 2, bonesMoved: moved, maxAngle, maxShift };
  }
  console.log(JSON.stringify(report));
} catch (e) {
  console.error(`${path}: ${e?.message ?? e}`);
  process.exit(1);
}
