#!/usr/bin/env node
// Which hands MediaPipe Holistic finds in a directory of PNG frames (one clip per directory,
// tracking across its frames as in legibility.mjs). For comparing renders of the same motion, e.g.
// from another camera:
//
//   gestura say help -o help.bvh
//   gestura render help.bvh --orbit 0,15,1.75,0,1.3,0 -o d/help.mp4 && ffmpeg -i d/help.mp4 d/%04d.png
//   node tools/legibility/hands-in-frames.mjs [--from 6] [--to 30] [--step 2] DIR ...
//
// Prints per directory the frames with the left (L) and right (R) hand found.
import fs from 'node:fs';
import path from 'node:path';

import {HolisticRunner} from './holistic-runner.mjs';

const options = {from: 0, to: Infinity, step: 2};
const dirs = [];
const args = process.argv.slice(2);
for (let i = 0; i < args.length; ++i) {
  if (args[i].startsWith('--')) {
    const key = args[i].slice(2);
    if (!(key in options) || i + 1 >= args.length) throw new Error(`unknown flag or missing value: ${args[i]}`);
    options[key] = Math.max(key === 'step' ? 1 : 0, parseInt(args[++i], 10));
  } else {
    dirs.push(args[i]);
  }
}
if (dirs.length === 0) throw new Error('no frame directory given');
const runner = await HolisticRunner.start();
try {
  for (const dir of dirs) {
    await runner.reset();
    const files = fs.readdirSync(dir).filter(f => f.endsWith('.png')).sort();
    let left = 0, right = 0, n = 0, line = '';
    for (let i = options.from; i <= options.to && i < files.length; i += options.step) {
      const r = await runner.detect(path.resolve(dir, files[i]));
      ++n, left += !!r.left, right += !!r.right;
      line += `${i}:${r.left ? 'L' : '-'}${r.right ? 'R' : '-'} `;
    }
    console.log(`${dir}: left ${left}/${n}, right ${right}/${n}, both ${left + right}/${2 * n}\n  ${line}`);
  }
} finally {
  await runner.close();
}
