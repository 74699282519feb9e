// Reads a pose-format ".pose" file (version 0.2, as `gestura say -o X.pose` writes it): header
// components and the frames × people × points × dims data with its confidence.
import fs from 'node:fs';

export function readPose(file) {
  const b = fs.readFileSync(file);
  let at = 0;
  const u16 = () => { const v = b.readUInt16LE(at); at += 2; return v; };
  const u32 = () => { const v = b.readUInt32LE(at); at += 4; return v; };
  const f32 = () => { const v = b.readFloatLE(at); at += 4; return v; };
  const str = () => { const n = u16(); const s = b.toString('utf8', at, at + n); at += n; return s; };
  const version = f32();
  if (Math.abs(version - 0.2) > 1e-3) throw new Error(`${file}: pose-format version ${version}, expected 0.2`);
  const width = u16(), height = u16(), depth = u16();
  const components = [];
  for (let c = u16(); c > 0; --c) {
    const name = str(), format = str();
    const points = u16(), limbs = u16(), colors = u16();
    const names = [];
    for (let i = 0; i < points; ++i) names.push(str());
    at += limbs * 4 + colors * 6;
    components.push({name, format, points: names});
  }
  const fps = f32(), frames = u32(), people = u16();
  const total = components.reduce((n, c) => n + c.points.length, 0);
  const dims = Math.max(...components.map(c => c.format.length)) - 1;
  const data = new Float32Array(b.buffer.slice(b.byteOffset + at, b.byteOffset + at + frames * people * total * dims * 4));
  at += frames * people * total * dims * 4;
  const confidence = new Float32Array(b.buffer.slice(b.byteOffset + at, b.byteOffset + at + frames * people * total * 4));
  const offset = name => {
    let o = 0;
    for (const c of components) {
      if (c.name === name) return o;
      o += c.points.length;
    }
    throw new Error(`${file}: no component ${name}`);
  };
  // Point `index` of component `name` in `frame` (first person): [x, y, z] and its confidence.
  const point = (frame, name, index) => {
    const k = frame * people * total + offset(name) + index;
    return {xyz: Array.from(data.slice(k * dims, k * dims + dims)), confidence: confidence[k]};
  };
  return {width, height, depth, fps, frames, people, components, point};
}
