// MediaPipe Holistic (the npm package, which bundles its model files) in Debian's headless chromium,
// driven by puppeteer-core. The page and the model files are served from a loopback HTTP server;
// nothing is fetched from outside.
//
//   const runner = await HolisticRunner.start();
//   await runner.reset();                       // before each clip: no tracking across clips
//   const r = await runner.detect('/abs/frame.png');
//   // r = {pose: [{x, y, z, visibility}] | null, face: [...] | null, left: [...] | null, right: [...] | null}
//   // x, y normalised to the image; left/right are the signer's own hands
//   await runner.overlay('/abs/frame.png', '/abs/out.png', truth)  // detected (red) over truth (green)
//   await runner.close();
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import {fileURLToPath} from 'node:url';

import puppeteer from 'puppeteer-core';

const here = path.dirname(fileURLToPath(import.meta.url));
const modelDir = path.join(here, 'node_modules', '@mediapipe', 'holistic');

const page = `<!doctype html><html><body><canvas id="c"></canvas>
<script src="/mp/holistic.js"></script><script>
const holistic = new Holistic({locateFile: f => '/mp/' + f});
holistic.setOptions({modelComplexity: 1, smoothLandmarks: false, refineFaceLandmarks: false,
                     minDetectionConfidence: 0.5, minTrackingConfidence: 0.5});
let deliver = null;
holistic.onResults(r => deliver && deliver(r));
const load = async url => { const img = new Image(); img.src = url; await img.decode(); return img; };
const plain = l => l ? l.map(p => ({x: p.x, y: p.y, z: p.z, visibility: p.visibility})) : null;
window.ready = holistic.initialize().then(() => true);
window.reset = async () => { holistic.reset(); };
window.detect = async url => {
  const img = await load(url);
  const results = new Promise(r => deliver = r);
  await holistic.send({image: img});
  const r = await results;
  return {pose: plain(r.poseLandmarks), face: plain(r.faceLandmarks), left: plain(r.leftHandLandmarks),
          right: plain(r.rightHandLandmarks), width: img.naturalWidth, height: img.naturalHeight};
};
// Draws the frame, gestura's own points (green) and the detected ones (red); returns a PNG data URL.
window.overlay = async (url, truth, detected) => {
  const img = await load(url);
  const c = document.getElementById('c');
  c.width = img.naturalWidth; c.height = img.naturalHeight;
  const g = c.getContext('2d');
  g.drawImage(img, 0, 0);
  const dot = (x, y, colour, r) => { g.fillStyle = colour; g.beginPath(); g.arc(x, y, r, 0, 7); g.fill(); };
  for (const p of truth) dot(p[0], p[1], 'rgba(0,220,0,0.9)', 2.5);
  for (const part of ['pose', 'face', 'left', 'right'])
    for (const p of detected[part] || []) dot(p.x * c.width, p.y * c.height, part === 'face' ? 'rgba(255,60,60,0.6)' : 'rgba(255,0,0,0.9)', 1.5);
  return c.toDataURL('image/png');
};
</script></body></html>`;

const types = {'.js': 'text/javascript', '.wasm': 'application/wasm', '.png': 'image/png', '.data': 'application/octet-stream',
               '.binarypb': 'application/octet-stream', '.tflite': 'application/octet-stream'};

export class HolisticRunner {
  static async start({chromium = process.env.CHROMIUM || '/usr/bin/chromium'} = {}) {
    if (!fs.existsSync(path.join(modelDir, 'holistic.js')))
      throw new Error(`${modelDir}: @mediapipe/holistic is not installed (make legibility installs it)`);
    const runner = new HolisticRunner();
    runner.frames = new Map();  // served path → file
    runner.server = http.createServer((req, res) => runner.serve(req, res));
    await new Promise(resolve => runner.server.listen(0, '127.0.0.1', resolve));
    runner.base = `http://127.0.0.1:${runner.server.address().port}`;
    runner.profile = fs.mkdtempSync(path.join(os.tmpdir(), 'gestura-chromium-'));
    runner.browser = await puppeteer.launch({
      executablePath: chromium, headless: true, userDataDir: runner.profile,
      args: ['--no-sandbox', '--headless', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
             '--disable-sync', '--no-first-run', '--enable-unsafe-swiftshader'],
      protocolTimeout: 600000,
    });
    runner.page = await runner.browser.newPage();
    runner.page.setDefaultTimeout(600000);
    await runner.page.goto(`${runner.base}/`);
    await runner.page.evaluate(() => window.ready);
    return runner;
  }

  serve(req, res) {
    const url = decodeURIComponent(req.url.split('?')[0]);
    let file = null;
    if (url === '/') {
      res.writeHead(200, {'content-type': 'text/html'});
      return res.end(page);
    }
    if (url.startsWith('/mp/')) file = path.join(modelDir, path.basename(url));
    if (url.startsWith('/frame/')) file = this.frames.get(url);
    if (!file || !fs.existsSync(file)) {
      res.writeHead(404);
      return res.end();
    }
    res.writeHead(200, {'content-type': types[path.extname(file)] || 'application/octet-stream'});
    fs.createReadStream(file).pipe(res);
  }

  url(file) {
    const served = `/frame/${this.frames.size}${path.extname(file)}`;
    this.frames.set(served, file);
    return served;
  }

  async reset() { await this.page.evaluate(() => window.reset()); }
  async detect(file) { return this.page.evaluate(u => window.detect(u), this.url(file)); }
  async overlay(file, out, truth, detected) {
    const data = await this.page.evaluate((u, t, d) => window.overlay(u, t, d), this.url(file), truth, detected);
    fs.writeFileSync(out, Buffer.from(data.split(',')[1], 'base64'));
  }
  async close() {
    await this.browser.close();
    this.server.close();
    fs.rmSync(this.profile, {recursive: true, force: true});
  }
}
