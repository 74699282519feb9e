#!/usr/bin/env node
// Legibility measured by a machine: gestura signs and sentences are rendered, MediaPipe Holistic
// looks at sampled frames, and its findings are scored against gestura's own landmarks (the .pose
// file `gestura say -o X.pose` writes, projected through the same camera as the video).
//
//   node tools/legibility/legibility.mjs [--gestura build/bin/gestura] [--out out/legibility]
//        [--size 1280x720] [--camera front] [--step 2] [--avatar SPEC] [ITEM ...]
//
// ITEM is English text for `gestura say` (default: house, sad, library and one sentence).
// Reported per item and over all:
//   hands found  — of the frames in which a hand is in the signing space (its wrist inside the
//                  image and above the hips), the share in which Holistic found that hand;
//   wrist error  — distance of the detected wrist (hand model) from gestura's projected wrist, in
//                  the signer's shoulder widths (the projected shoulders' distance in that frame);
//   mouth        — correlation over frames between the detected mouth opening (inner lips 13–14
//                  over the mouth width 61–291) and gestura's own, and whether it follows (r ≥ 0.5).
// Frames and overlays (green: gestura, red: detected) are kept under --out for looking at.
import {execFileSync} from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';

import {HolisticRunner} from './holistic-runner.mjs';
import {readPose} from './pose-file.mjs';

const defaults = ['house', 'sad', 'library', 'my mother lives in a big house'];
const options = {gestura: 'build/bin/gestura', out: 'out/legibility', size: '1280x720', camera: 'front', step: 2, avatar: ''};
const items = [];
const args = process.argv.slice(2);
for (let i = 0; i < args.length; ++i) {
  const a = args[i];
  if (a.startsWith('--')) {
    const key = a.slice(2);
    if (!(key in options) || i + 1 >= args.length) throw new Error(`unknown flag or missing value: ${a}`);
    options[key] = key === 'step' ? Math.max(1, parseInt(args[++i], 10)) : args[++i];
  } else {
    items.push(a);
  }
}
if (items.length === 0) items.push(...defaults);

const run = (cmd, argv) => execFileSync(cmd, argv, {stdio: ['ignore', 'pipe', 'pipe']}).toString();
const slug = text => text.toLowerCase().replace(/[^a-z0-9]+/g, '-').replace(/^-|-$/g, '');
const distance = (a, b) => Math.hypot(a[0] - b[0], a[1] - b[1]);
const mean = v => v.length ? v.reduce((s, x) => s + x, 0) / v.length : NaN;
const median = v => {
  if (!v.length) return NaN;
  const s = [...v].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : 0.5 * (s[s.length / 2 - 1] + s[s.length / 2]);
};
const correlation = (a, b) => {
  if (a.length < 3) return NaN;
  const ma = mean(a), mb = mean(b);
  let sab = 0, saa = 0, sbb = 0;
  for (let i = 0; i < a.length; ++i) sab += (a[i] - ma) * (b[i] - mb), saa += (a[i] - ma) ** 2, sbb += (b[i] - mb) ** 2;
  return saa > 0 && sbb > 0 ? sab / Math.sqrt(saa * sbb) : NaN;
};

fs.mkdirSync(options.out, {recursive: true});
const started = Date.now();
const runner = await HolisticRunner.start();
const results = [];
try {
  for (const text of items) {
    const name = slug(text);
    const dir = path.join(options.out, name);
    fs.rmSync(dir, {recursive: true, force: true});
    fs.mkdirSync(path.join(dir, 'frames'), {recursive: true});
    const flags = ['--size', options.size, '--camera', options.camera, ...(options.avatar ? ['--avatar', options.avatar] : [])];
    const video = path.join(dir, `${name}.mp4`), poseFile = path.join(dir, `${name}.pose`);
    run(options.gestura, ['say', text, '-o', video, ...flags]);
    run(options.gestura, ['say', text, '-o', poseFile, ...flags]);
    run('ffmpeg', ['-loglevel', 'error', '-i', video, '-fps_mode', 'passthrough', path.join(dir, 'frames', '%04d.png')]);
    const truth = readPose(poseFile);
    const frameFiles = fs.readdirSync(path.join(dir, 'frames')).filter(f => f.endsWith('.png')).sort();
    const frames = Math.min(frameFiles.length, truth.frames);
    const W = truth.width, H = truth.height;
    const item = {text, frames, sampled: 0, hands: {left: {inSpace: 0, found: 0, errors: [], poseErrors: [], swapped: 0},
                                                     right: {inSpace: 0, found: 0, errors: [], poseErrors: [], swapped: 0}},
                  faceFound: 0, bodyFound: 0, mouth: {truth: [], detected: []}, perFrame: []};
    await runner.reset();
    const samples = [];
    for (let f = 0; f < frames; f += Number(options.step)) samples.push(f);
    const overlayAt = new Set([samples[Math.floor(samples.length * 0.4)], samples[Math.floor(samples.length * 0.6)]]);
    for (const f of samples) {
      const file = path.resolve(dir, 'frames', frameFiles[f]);
      const t0 = Date.now();
      const r = await runner.detect(file);
      const seconds = (Date.now() - t0) / 1000;
      ++item.sampled;
      if (r.pose) ++item.bodyFound;
      if (r.face) ++item.faceFound;
      const P = i => truth.point(f, 'POSE_LANDMARKS', i).xyz;
      const shoulderWidth = distance(P(11), P(12));
      const hipsY = 0.5 * (P(23)[1] + P(24)[1]);
      const row = {frame: f, seconds, pose: !!r.pose, face: !!r.face, left: !!r.left, right: !!r.right};
      for (const [side, wristIndex, other] of [['left', 15, 'right'], ['right', 16, 'left']]) {
        const w = truth.point(f, 'POSE_LANDMARKS', wristIndex);
        const inSpace = w.confidence > 0 && w.xyz[0] >= 0 && w.xyz[0] < W && w.xyz[1] >= 0 && w.xyz[1] < H && w.xyz[1] < hipsY;
        row[`${side}InSpace`] = inSpace;
        if (!inSpace) continue;
        const h = item.hands[side];
        ++h.inSpace;
        if (r[side]) {
          ++h.found;
          const detected = [r[side][0].x * W, r[side][0].y * H];
          const error = distance(detected, w.xyz) / shoulderWidth;
          h.errors.push(error);
          row[`${side}Error`] = error;
          const otherWrist = truth.point(f, 'POSE_LANDMARKS', other === 'left' ? 15 : 16).xyz;
          if (distance(detected, otherWrist) < distance(detected, w.xyz)) ++h.swapped;
        }
        if (r.pose) h.poseErrors.push(distance([r.pose[wristIndex].x * W, r.pose[wristIndex].y * H], w.xyz) / shoulderWidth);
      }
      const F = i => truth.point(f, 'FACE_LANDMARKS', i);
      if (r.face && F(13).confidence > 0 && F(61).confidence > 0) {
        const opening = (a, b, l, rr) => distance(a, b) / Math.max(1e-6, distance(l, rr));
        const px = i => [r.face[i].x * W, r.face[i].y * H];
        item.mouth.truth.push(opening(F(13).xyz, F(14).xyz, F(61).xyz, F(291).xyz));
        item.mouth.detected.push(opening(px(13), px(14), px(61), px(291)));
      }
      item.perFrame.push(row);
      if (overlayAt.has(f)) {
        const points = [];
        for (const [component, count] of [['POSE_LANDMARKS', 25], ['LEFT_HAND_LANDMARKS', 21], ['RIGHT_HAND_LANDMARKS', 21], ['FACE_LANDMARKS', 468]])
          for (let i = 0; i < count; ++i) {
            const p = truth.point(f, component, i);
            if (p.confidence > 0) points.push(p.xyz);
          }
        await runner.overlay(file, path.join(dir, `overlay-${String(f).padStart(4, '0')}.png`), points, r);
      }
      process.stderr.write(`${name} frame ${f}/${frames}: body ${row.pose ? 'y' : 'n'} face ${row.face ? 'y' : 'n'} ` +
                           `left ${row.left ? 'y' : 'n'} right ${row.right ? 'y' : 'n'} (${seconds.toFixed(1)} s)\n`);
    }
    item.mouth.correlation = correlation(item.mouth.truth, item.mouth.detected);
    results.push(item);
  }
} finally {
  await runner.close();
}

// The report.
const pct = (a, b) => b ? `${(100 * a / b).toFixed(0)} % (${a}/${b})` : '—';
const num = x => Number.isFinite(x) ? x.toFixed(3) : '—';
const lines = [];
lines.push(`MediaPipe Holistic (modelComplexity 1) on gestura renders, ${options.size}, camera ${options.camera}, every ${options.step}. frame` +
           `${options.avatar ? `, avatar ${options.avatar}` : ''}; ${((Date.now() - started) / 1000).toFixed(0)} s`);
lines.push('');
lines.push('| item | frames sampled | body found | face found | left hand found | right hand found | hand found (both) | wrist error median / mean (shoulder widths) | ≤ 0.10 | pose-model wrist error median | swapped | mouth r |');
lines.push('|---|---|---|---|---|---|---|---|---|---|---|---|');
const total = {sampled: 0, body: 0, face: 0, inSpace: {left: 0, right: 0}, found: {left: 0, right: 0}, errors: [], poseErrors: [], swapped: 0, mt: [], md: []};
for (const it of results) {
  const L = it.hands.left, R = it.hands.right;
  const errors = [...L.errors, ...R.errors], poseErrors = [...L.poseErrors, ...R.poseErrors];
  lines.push(`| ${it.text} | ${it.sampled} of ${it.frames} | ${pct(it.bodyFound, it.sampled)} | ${pct(it.faceFound, it.sampled)} | ` +
             `${pct(L.found, L.inSpace)} | ${pct(R.found, R.inSpace)} | ${pct(L.found + R.found, L.inSpace + R.inSpace)} | ` +
             `${num(median(errors))} / ${num(mean(errors))} | ${pct(errors.filter(e => e <= 0.10).length, errors.length)} | ` +
             `${num(median(poseErrors))} | ${L.swapped + R.swapped} | ${num(it.mouth.correlation)} |`);
  total.sampled += it.sampled, total.body += it.bodyFound, total.face += it.faceFound;
  for (const s of ['left', 'right']) total.inSpace[s] += it.hands[s].inSpace, total.found[s] += it.hands[s].found;
  total.errors.push(...errors), total.poseErrors.push(...poseErrors), total.swapped += L.swapped + R.swapped;
  total.mt.push(...it.mouth.truth), total.md.push(...it.mouth.detected);
}
const allFound = total.found.left + total.found.right, allInSpace = total.inSpace.left + total.inSpace.right;
const mouthR = correlation(total.mt, total.md);
lines.push(`| **all** | ${total.sampled} | ${pct(total.body, total.sampled)} | ${pct(total.face, total.sampled)} | ` +
           `${pct(total.found.left, total.inSpace.left)} | ${pct(total.found.right, total.inSpace.right)} | ${pct(allFound, allInSpace)} | ` +
           `${num(median(total.errors))} / ${num(mean(total.errors))} | ${pct(total.errors.filter(e => e <= 0.10).length, total.errors.length)} | ` +
           `${num(median(total.poseErrors))} | ${total.swapped} | ${num(mouthR)} |`);
lines.push('');
const found = allInSpace ? allFound / allInSpace : 0;
lines.push(`goals: hands found ≥ 95 %: ${found >= 0.95 ? 'met' : 'not met'} (${(100 * found).toFixed(0)} %); ` +
           `wrist error ≤ 0.10 shoulder widths (median): ${median(total.errors) <= 0.10 ? 'met' : 'not met'}; ` +
           `mouth opening follows the mouthing (r ≥ 0.5): ${mouthR >= 0.5 ? 'yes' : 'no'}`);
const report = lines.join('\n');
fs.writeFileSync(path.join(options.out, 'report.md'), report + '\n');
fs.writeFileSync(path.join(options.out, 'report.json'), JSON.stringify({options, items: results}, null, 1));
console.log(report);
