// <gestura-player> on a page of another origin, from one script tag: it signs the text a reader
// selects, takes {type: 'sigml', data} like UPF Performs' iframe, and says clearly when its server
// cannot be reached.
import { createServer } from 'node:http';
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { args, check, failed, launchBrowser, skipUnlessBrowser, startServer, watchErrors } from './harness.mjs';

const chromium = skipUnlessBrowser();
const options = args();
const server = await startServer(options.gestura);

// The host page, served from another origin than the gestura server.
const hostPage = (gesturaServer, attributes) => `<!doctype html><html lang="en"><head><meta charset="utf-8"><title>host</title>
<link rel="icon" href="data:,"><script src="${gesturaServer}/widget.js" defer></script></head><body>
<p id="text">Hello, how are you?</p>
<gestura-player ${attributes} style="width: 480px; height: 480px"></gestura-player></body></html>`;
let page404 = '';
const host = createServer((req, res) => {
  res.setHeader('Content-Type', 'text/html; charset=utf-8');
  if (req.url === '/selection') res.end(hostPage(server.url, 'selection'));
  else if (req.url === '/down') res.end(hostPage(server.url, 'server="http://127.0.0.1:9"'));
  else { page404 = req.url; res.statusCode = 404; res.end(); }
});
await new Promise((r) => host.listen(0, '127.0.0.1', r));
const hostUrl = `http://127.0.0.1:${host.address().port}`;

const browser = await launchBrowser(chromium);
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1000, height: 700 });
  const errors = watchErrors(page);
  await page.goto(`${hostUrl}/selection`, { waitUntil: 'load' });
  await page.evaluate(() => new Promise((resolve) => {
    const el = document.querySelector('gestura-player');
    if (el.ready) resolve(); else el.addEventListener('ready', resolve, { once: true });
  }));
  check(true, 'the widget loaded its player from one script tag');
  const frame = () => page.frames().find((f) => f.url().includes('/embed.html'));

  // The reader selects the paragraph.
  const playing = page.evaluate(() => new Promise((resolve) => {
    document.querySelector('gestura-player').addEventListener('playing', (e) => resolve(e.detail), { once: true });
  }));
  await page.evaluate(() => {
    const range = document.createRange();
    range.selectNodeContents(document.getElementById('text'));
    getSelection().removeAllRanges();
    getSelection().addRange(range);
    document.dispatchEvent(new MouseEvent('mouseup'));  // the end of the reader's selecting gesture
  });
  const detail = await playing;
  console.log(`selection signed: ${detail.glosses.map((g) => g.gloss).join(' ')}`);
  check(detail.glosses.some((g) => g.gloss === 'HELLO'), 'the selected text is signed');
  // From where the wrist is as the clip starts.
  const rest = await frame().evaluate(() => window.gestura.jointPosition('r_wrist'));
  let farthest = 0;
  for (let i = 0; i < 25; ++i) {
    const p = await frame().evaluate(() => window.gestura.jointPosition('r_wrist'));
    farthest = Math.max(farthest, Math.hypot(p[0] - rest[0], p[1] - rest[1], p[2] - rest[2]));
    await new Promise((r) => setTimeout(r, 100));
  }
  console.log(`right wrist moved up to ${(farthest * 100).toFixed(1)} cm in the widget`);
  check(farthest > 0.10, 'the widget avatar moves its right wrist by more than 10 cm');
  if (options.out) {
    mkdirSync(options.out, { recursive: true });
    await page.screenshot({ path: join(options.out, 'widget.png') });
  }

  // A page written for UPF Performs posts SiGML.
  const sigml = '<sigml><hns_sign gloss="TEST"><hamnosys_manual><hamflathand/><hamextfingeru/><hampalml/><hamshoulders/></hamnosys_manual></hns_sign></sigml>';
  const second = page.evaluate(() => new Promise((resolve) => {
    document.querySelector('gestura-player').addEventListener('playing', (e) => resolve(e.detail), { once: true });
  }));
  await page.evaluate((data) => document.querySelector('gestura-player').post({ type: 'sigml', data }), sigml);
  const signed = await second;
  check(signed.duration > 0, `postMessage {type: 'sigml'} is signed (${signed.duration.toFixed(2)} s)`);
  for (const e of errors) console.log(e);
  check(errors.length === 0, 'no console errors with a reachable server');

  // The server is down: the widget says so.
  const down = await browser.newPage();
  await down.goto(`${hostUrl}/down`, { waitUntil: 'load' });
  await down.waitForFunction(() => {
    const box = document.querySelector('gestura-player')?.shadowRoot?.querySelector('.message');
    return box && !box.hidden;
  }, { timeout: 20000 });
  const text = await down.evaluate(() => document.querySelector('gestura-player').shadowRoot.querySelector('.message').textContent);
  console.log(`unreachable: ${text}`);
  check(/cannot reach/.test(text), 'an unreachable server is told clearly');
  if (options.out) await down.screenshot({ path: join(options.out, 'widget-down.png') });
  check(!page404, `the host page asked only for what it serves (${page404 || 'ok'})`);
} finally {
  await browser.close();
  host.close();
  server.stop();
}
process.exit(failed() ? 1 : 0);
