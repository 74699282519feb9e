// Driving an avatar with one's body, in headless chromium: a video of gestura's own avatar signing
// HELLO (made here, at test time: `gestura say` → .mp4 → .y4m by the ffmpeg CLI) is the fake camera
// of client A. A's page runs MediaPipe Holistic on it and sends the landmarks to the room; client B
// sees A's avatar's right wrist follow the video's: it moves more than 10 cm, the way the filmed
// wrist moved (the .json joint track of the same sentence). B, whose camera is refused, is told so.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { args, check, failed, launchBrowser, skipUnlessBrowser, startServer, watchErrors, webRoot } from './harness.mjs';

const chromium = skipUnlessBrowser();
const options = args();
if (!existsSync(join(webRoot, 'node_modules', '@mediapipe', 'holistic', 'holistic.js')))
  throw new Error('web/node_modules/@mediapipe/holistic is missing (scripts/setup-deps.sh installs web/package.json)');
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
const run = (cmd, argv) => {
  const r = spawnSync(cmd, argv, { encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`${cmd} ${argv.join(' ')} failed: ${r.error ?? ''}${r.stderr}`);
};

// The camera's video: the avatar signs HELLO (rest → salute at the forehead → rest), then holds at
// rest for a second; chromium loops it.
const work = mkdtempSync(join(tmpdir(), 'gestura-capture-test-'));
const video = join(work, 'hello.y4m');
run(options.gestura, ['say', 'hello', '-o', join(work, 'hello.json'), '--fps', '15']);
run(options.gestura, ['say', 'hello', '-o', join(work, 'hello.mp4'), '--size', '640x480', '--fps', '15']);
run('ffmpeg', ['-loglevel', 'error', '-y', '-i', join(work, 'hello.mp4'), '-vf', 'tpad=stop_mode=clone:stop_duration=1,fps=15',
               '-pix_fmt', 'yuv420p', video]);
// Where the filmed right wrist went: its farthest place from rest (model space, metres).
const track = JSON.parse(readFileSync(join(work, 'hello.json'), 'utf8'));
const wristAt = (frame) => { const k = track.joints.indexOf('r_wrist'); const f = track.frames[frame]; return Array.isArray(f[k]) ? f[k] : f.slice(3 * k, 3 * k + 3); };
const sub = (a, b) => a.map((v, i) => v - b[i]);
const len = (a) => Math.hypot(...a);
const rest = wristAt(0);
let truth = [0, 0, 0];
for (let f = 0; f < track.frames.length; ++f) { const d = sub(wristAt(f), rest); if (len(d) > len(truth)) truth = d; }
console.log(`the filmed right wrist moves ${(len(truth) * 100).toFixed(1)} cm from rest, toward [${truth.map((v) => v.toFixed(2))}]`);

const server = await startServer(options.gestura);
const browsers = [];
async function open(name, extraArgs = []) {
  const browser = await launchBrowser(chromium, extraArgs);
  browsers.push(browser);
  const page = await browser.newPage();
  await page.setViewport({ width: 900, height: 560 });
  const errors = watchErrors(page);
  await page.goto(`${server.url}/room.html?room=capture&name=${name}&look=default`, { waitUntil: 'load' });
  await page.waitForFunction(() => document.querySelectorAll('#look option').length > 0, { timeout: 30000, polling: 100 });
  await page.click('#join-button');
  await page.waitForFunction(() => window.gesturaRoom.you, { timeout: 60000, polling: 100 });
  return { page, errors, name, id: await page.evaluate(() => window.gesturaRoom.you.id) };
}
// A's right wrist as B's page shows it, in A's avatar's own frame (its seat turns it in the room).
const wristSeen = (viewer, id) => viewer.page.evaluate((who) => {
  const room = window.gesturaRoom, f = room.figures.get(who);
  const node = f?.root?.getObjectByName('r_wrist');
  if (!node) return null;
  const v = f.root.worldToLocal(node.getWorldPosition(f.root.position.clone()));
  return [v.x, v.y, v.z];
}, id);

try {
  const a = await open('Ana', ['--use-fake-ui-for-media-stream', '--use-fake-device-for-media-stream', `--use-file-for-fake-video-capture=${video}`]);
  const b = await open('Ben');
  await b.page.waitForFunction((id) => window.gesturaRoom.figures.get(id)?.root, { timeout: 90000, polling: 100 }, a.id);
  const restSeen = await wristSeen(b, a.id);

  // B's camera is refused: the page says so, and the button stays usable.
  await b.page.evaluate(() => { navigator.mediaDevices.getUserMedia = () => Promise.reject(new DOMException('Permission denied', 'NotAllowedError')); });
  await b.page.focus('#camera-button');
  await b.page.keyboard.press('Enter');
  await b.page.waitForFunction(() => document.getElementById('camera-status').classList.contains('error'), { timeout: 10000, polling: 100 });
  const refusal = await b.page.$eval('#camera-status', (e) => e.textContent);
  console.log(`B's page: ${refusal}`);
  check(/refused/.test(refusal), 'a refused camera is reported in words');
  check(!(await b.page.$eval('#camera-button', (e) => e.disabled)) && (await b.page.$eval('#camera-button', (e) => e.getAttribute('aria-pressed'))) === 'false',
        'the camera button is usable again after a refusal');

  // A's camera: the keyboard starts it; Holistic runs in A's page and the landmarks go to the room.
  await a.page.focus('#camera-button');
  await a.page.keyboard.press('Enter');
  await a.page.waitForFunction(() => window.gesturaCapture.sent > 0 || document.getElementById('camera-status').classList.contains('error'),
                               { timeout: 180000, polling: 200 });
  const started = await a.page.evaluate(() => ({ sent: window.gesturaCapture.sent, status: document.getElementById('camera-status').textContent }));
  console.log(`A's page: ${started.status}`);
  check(started.sent > 0, 'A\'s page tracks the body in the fake camera and sends landmarks');

  // B watches A's avatar: the right wrist's farthest place from rest while the video loops.
  let farthest = [0, 0, 0];
  const began = Date.now();
  while (Date.now() - began < 20000) {
    const p = await wristSeen(b, a.id);
    const d = sub(p, restSeen);
    if (len(d) > len(farthest)) farthest = d;
    if (len(farthest) > 0.3 && Date.now() - began > 6000) break;
    await sleep(100);
  }
  const cos = farthest.reduce((s, v, i) => s + v * truth[i], 0) / (len(farthest) * len(truth) || 1);
  const rate = await a.page.evaluate(() => window.gesturaCapture.sent);
  console.log(`B sees A's right wrist move ${(len(farthest) * 100).toFixed(1)} cm toward [${farthest.map((v) => v.toFixed(2))}]; ` +
              `cosine with the filmed wrist's move ${cos.toFixed(2)}; A sent ${rate} landmarks messages in ${((Date.now() - began) / 1000).toFixed(1)} s`);
  check(len(farthest) > 0.10, 'B sees A\'s avatar\'s right wrist move more than 10 cm');
  check(cos > 0.7, 'it moves the way the filmed wrist moved (cosine > 0.7)');

  if (options.out) {
    mkdirSync(options.out, { recursive: true });
    await b.page.screenshot({ path: join(options.out, 'capture-b.png') });
    await a.page.screenshot({ path: join(options.out, 'capture-a.png') });
  }
  await a.page.click('#camera-button');
  check((await a.page.$eval('#camera-button', (e) => e.getAttribute('aria-pressed'))) === 'false', 'the camera stops');
  for (const x of [a, b]) {
    for (const e of x.errors) console.log(`${x.name}: ${e}`);
    check(x.errors.length === 0, `no console errors for ${x.name}`);
  }
} finally {
  for (const browser of browsers) await browser.close();
  server.stop();
  rmSync(work, { recursive: true, force: true });
}
process.exit(failed() ? 1 : 0);
