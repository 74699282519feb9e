// The gestura player: the avatar (GET /api/avatar.glb, downloaded once and cached by the browser)
// in a three.js scene, signing the small animation clips the server answers (POST /api/say or
// /api/sign with ?format=glb). The page (app.js) and the embeddable <gestura-player> (widget.js)
// both use it.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

// Camera presets: position and the point looked at, in metres (+Y up, the avatar faces +Z).
export const CAMERAS = {
  front: { position: [0, 1.4, 2.7], target: [0, 1.32, 0] },
  'three-quarter': { position: [1.75, 1.45, 2.05], target: [0, 1.32, 0] },
  side: { position: [2.7, 1.4, 0.2], target: [0, 1.32, 0] },
  hands: { position: [0, 1.3, 1.55], target: [0, 1.28, 0.2] },
  face: { position: [0, 1.62, 0.75], target: [0, 1.6, 0] },
};

// The JSON chunk of a .glb (the timeline rides in the animation's extras).
export function glbJson(buffer) {
  const view = new DataView(buffer);
  if (view.getUint32(0, true) !== 0x46546c67) throw new Error('not a binary glTF');
  const length = view.getUint32(12, true);
  return JSON.parse(new TextDecoder().decode(new Uint8Array(buffer, 20, length)));
}

export class ServerError extends Error {
  constructor(status, error) {
    super(error?.message ?? `HTTP ${status}`);
    this.status = status;
    this.field = error?.field;
    this.category = error?.category;
  }
}

export class Player extends EventTarget {
  // container: an element the canvas fills; server: the API's origin ('' for the page's own).
  constructor(container, { server = '', background = 0xeef1f5 } = {}) {
    super();
    this.server = server.replace(/\/$/, '');
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
    this.renderer.outputColorSpace = THREE.SRGBColorSpace;
    this.canvas = this.renderer.domElement;
    container.appendChild(this.canvas);
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(background);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x8d8d8d, 2.2));
    const key = new THREE.DirectionalLight(0xffffff, 2.0);
    key.position.set(1.5, 3, 2.5);
    this.scene.add(key);
    const floor = new THREE.Mesh(new THREE.CircleGeometry(1.2, 48), new THREE.MeshStandardMaterial({ color: 0xd5dae2 }));
    floor.rotation.x = -Math.PI / 2;
    this.scene.add(floor);
    this.camera = new THREE.PerspectiveCamera(30, 1, 0.05, 50);
    this.controls = new OrbitControls(this.camera, this.canvas);
    this.controls.enableDamping = true;
    this.setCamera('front');
    this.clock = new THREE.Clock();
    this.mixer = null;
    this.action = null;
    this.timeline = null;
    this.speed = 1;
    this.currentGloss = -1;
    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(container);
    this.container = container;
    this.resize();
    this.renderer.setAnimationLoop(() => this.frame());
  }

  resize() {
    const w = Math.max(1, this.container.clientWidth), h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
  }

  setCamera(name) {
    const c = CAMERAS[name] ?? CAMERAS.front;
    this.camera.position.set(...c.position);
    this.controls.target.set(...c.target);
    this.controls.update();
  }

  async fetchOk(path, init) {
    let response;
    try {
      response = await fetch(this.server + path, init);
    } catch (e) {
      throw new ServerError(0, { message: `the gestura server at ${this.server || location.origin} cannot be reached`, category: 'unreachable' });
    }
    if (!response.ok) {
      let error = null;
      try { error = (await response.json()).error; } catch { /* not JSON */ }
      throw new ServerError(response.status, error);
    }
    return response;
  }

  // Another built-in look (GET /api/looks): the next loadAvatar() and every clip after use it.
  async setLook(look) {
    if (look === (this.look ?? 'default')) return;
    this.look = look;
    if (this.action) { this.action.stop(); this.action = null; }
    if (this.avatar) this.scene.remove(this.avatar);
    this.avatar = null;
    this.avatarLoading = null;
    await this.loadAvatar();
  }

  // Downloads and shows the avatar (once per look; the browser caches it).
  loadAvatar() {
    if (this.avatar) return Promise.resolve(this.avatar);
    this.avatarLoading ??= this.fetchAvatar();
    return this.avatarLoading;
  }

  async fetchAvatar() {
    const look = this.look ?? 'default';
    const buffer = await (await this.fetchOk(`/api/avatar.glb${look === 'default' ? '' : `?look=${encodeURIComponent(look)}`}`)).arrayBuffer();
    const gltf = await new GLTFLoader().parseAsync(buffer, '');
    this.avatar = gltf.scene;
    this.scene.add(this.avatar);
    this.morphMeshes = [];
    this.avatar.traverse((o) => { if (o.morphTargetInfluences) this.morphMeshes.push(o); });
    this.mixer = new THREE.AnimationMixer(this.avatar);
    this.mixer.addEventListener('finished', () => this.dispatchEvent(new Event('finished')));
    this.dispatchEvent(new Event('ready'));
    return this.avatar;
  }

  // English text → signing. Resolves with the timeline once playback has started.
  say(text, options = {}) {
    return this.perform('/api/say', { text, ...options });
  }
  // One sign: {hamnosys} | {names} | {sigml: '<sigml>…'}.
  sign(source) {
    return this.perform('/api/sign', source);
  }

  async perform(path, body) {
    await this.loadAvatar();
    const look = this.look ?? 'default';
    const response = await this.fetchOk(path + '?format=glb', {
      method: 'POST', headers: { 'Content-Type': 'application/json', Accept: 'model/gltf-binary' },
      body: JSON.stringify(look === 'default' ? body : { ...body, look }),
    });
    const buffer = await response.arrayBuffer();
    this.lastClipBytes = buffer.byteLength;
    const json = glbJson(buffer);
    const gltf = await new GLTFLoader().parseAsync(buffer, '');
    const clip = gltf.animations[0];
    this.play(clip, json.animations?.[0]?.extras ?? {});
    return this.timeline;
  }

  // The clip's face track drives the stand-in mesh "face_weights"; the avatar's meshes have the
  // same targets in the same order, so the track is copied onto each of them.
  bindClip(clip) {
    const tracks = [];
    for (const track of clip.tracks) {
      if (track.name.startsWith('face_weights.')) {
        for (const mesh of this.morphMeshes) {
          const copy = track.clone();
          copy.name = `${mesh.uuid}.morphTargetInfluences`;
          tracks.push(copy);
        }
      } else {
        tracks.push(track);
      }
    }
    return new THREE.AnimationClip(clip.name, clip.duration, tracks);
  }

  play(clip, timeline) {
    if (this.action) {
      this.action.stop();
      this.mixer.uncacheAction(this.action.getClip());
    }
    this.timeline = timeline;
    this.currentGloss = -1;
    this.action = this.mixer.clipAction(this.bindClip(clip));
    this.action.setLoop(THREE.LoopOnce, 1);
    this.action.clampWhenFinished = true;
    this.mixer.timeScale = this.speed;
    this.action.play();
    this.dispatchEvent(new CustomEvent('timeline', { detail: timeline }));
  }

  setSpeed(speed) {
    this.speed = Math.min(2, Math.max(0.25, speed));
    if (this.mixer) this.mixer.timeScale = this.speed;
  }
  get paused() { return !this.action || this.action.paused; }
  pause(paused = true) { if (this.action) this.action.paused = paused; }
  replay() {
    if (!this.action) return;
    this.action.reset();
    this.action.paused = false;
    this.action.play();
  }
  // One frame (1/30 s of the clip) forward or back, paused.
  step(frames = 1) {
    if (!this.action) return;
    this.action.paused = true;
    const d = this.action.getClip().duration;
    this.action.time = Math.min(d, Math.max(0, this.action.time + frames / 30));
    this.mixer.update(0);
  }
  get time() { return this.action ? this.action.time : 0; }

  // World position of a joint (metres), for tests and tools.
  jointPosition(name) {
    const node = this.avatar?.getObjectByName(name);
    if (!node) return null;
    const p = node.getWorldPosition(new THREE.Vector3());
    return [p.x, p.y, p.z];
  }

  frame() {
    const dt = this.clock.getDelta();
    if (this.mixer) this.mixer.update(dt);
    this.controls.update();
    if (this.timeline?.glosses && this.action) {
      const t = this.action.time;
      const index = this.timeline.glosses.findIndex((g) => t >= g.start && t < g.end);
      if (index !== this.currentGloss) {
        this.currentGloss = index;
        this.dispatchEvent(new CustomEvent('gloss', { detail: { index, gloss: this.timeline.glosses[index] } }));
      }
    }
    this.renderer.render(this.scene, this.camera);
  }

  dispose() {
    this.renderer.setAnimationLoop(null);
    this.resizeObserver.disconnect();
    this.controls.dispose();
    this.renderer.dispose();
    this.canvas.remove();
  }
}
