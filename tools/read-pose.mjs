// Reads a .pose file with pose-format's own JavaScript reader (the npm package sign.mt uses) and
// prints what it found as JSON: header, fps, frame count and the points of one frame.
//   node tools/read-pose.mjs FILE.pose [FRAME]
import fs from 'node:fs';

// The package's index re-exports without file extensions (made for bundlers); its parser is plain ESM.
import {parsePose} from 'pose-format/dist/parser.js';

const [file, frameArg] = process.argv.slice(2);
const pose = parsePose(fs.readFileSync(file));
const frame = Number(frameArg ?? 0);
const person = pose.body.frames[frame].people[0];
const points = {};
for (const c of pose.header.components) points[c.name] = person[c.name].map(p => [p.X, p.Y, p.Z ?? 0, p.C]);
console.log(JSON.stringify({
  version: pose.header.version, width: pose.header.width, height: pose.header.height,
  components: pose.header.components.map(c => ({name: c.name, format: c.format, points: c.points, limbs: c.limbs.length})),
  fps: pose.body.fps, frames: pose.body._frames, people: pose.body._people, frame, points,
}));
