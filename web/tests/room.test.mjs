// A shared room in headless chromium: two clients join one room with different looks, each types a
// sentence, and each sees the other's avatar sign it (the other's right wrist, read from the page,
// moves by more than 10 cm); the host walks to the signer and turns toward them; a late joiner sees both avatars and
// the sentence still playing.
import { mkdirSync } from 'node:fs';
import { join } from 'node:path';
import { args, check, failed, launchBrowser, skipUnlessBrowser, startServer, watchErrors } from './harness.mjs';

const chromium = skipUnlessBrowser();
const options = args();
const server = await startServer(options.gestura);
// One browser per client, as people in different places have: a tab in the background of a shared
// browser draws no frames.
const browsers = [];
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

// A browser with the room page open, not yet joined.
async function open(name, look) {
  const browser = await launchBrowser(chromium);
  browsers.push(browser);
  const page = await browser.newPage();
  await page.setViewport({ width: 900, height: 560 });  // three software-rendered browsers on two cores
  const errors = watchErrors(page);
  await page.goto(`${server.url}/room.html?room=test&name=${name}&look=${look}`, { waitUntil: 'load' });
  await page.waitForFunction((l) => [...document.querySelectorAll('#look option')].some((o) => o.value === l), { timeout: 30000, polling: 100 }, look);
  await page.select('#look', look);
  return { page, errors, name };
}
async function enter(x) {
  await x.page.click('#join-button');
  await x.page.waitForFunction(() => window.gesturaRoom.you, { timeout: 60000, polling: 100 });
  x.id = await x.page.evaluate(() => window.gesturaRoom.you.id);
  return x;
}
const client = async (name, look) => enter(await open(name, look));

// Waits until `viewer` shows `who`'s avatar, then samples its right wrist while it signs: the
// farthest it gets from where it was when the clip started.
async function wristTravel(viewer, who, seconds = 6) {
  await viewer.page.waitForFunction((id) => window.gesturaRoom.figures.get(id)?.root, { timeout: 90000, polling: 100 }, who);
  try {
    await viewer.page.waitForFunction((id) => { const f = window.gesturaRoom.figures.get(id); return f?.clip && window.gesturaRoom.serverNow() >= f.clip.start; },
                                      { timeout: 60000, polling: 100 }, who);
  } catch (e) {
    console.log(`${viewer.name} never shows ${who} signing: ${await viewer.page.evaluate((id) => {
      const r = window.gesturaRoom, f = r.figures.get(id);
      return JSON.stringify({ now: r.serverNow(), clip: f?.clip, action: !!f?.action, log: r.log });
    }, who)}`);
    return 0;
  }
  const start = await viewer.page.evaluate((id) => window.gesturaRoom.jointPosition(id, 'r_wrist'), who);
  let farthest = 0;
  for (let i = 0; i < seconds * 10; ++i) {
    const p = await viewer.page.evaluate((id) => window.gesturaRoom.jointPosition(id, 'r_wrist'), who);
    farthest = Math.max(farthest, Math.hypot(p[0] - start[0], p[1] - start[1], p[2] - start[2]));
    if (farthest > 0.2) break;
    await sleep(100);
  }
  return farthest;
}

try {
  const a = await client('Ana', 'ana');
  const b = await client('Ben', 'ben');
  const late = await open('Chidi', 'chidi');
  // The late joiner has the looks in its cache already (a returning visitor): what is measured is
  // joining mid-sentence, not downloading avatars.
  await late.page.evaluate(() => window.gesturaRoom.preload(['ana', 'ben', 'chidi', 'default']));
  check(a.id !== b.id, `two participants (${a.id}, ${b.id})`);
  await a.page.waitForFunction((id) => window.gesturaRoom.figures.get(id)?.root, { timeout: 90000, polling: 100 }, b.id);
  check(true, 'A sees B\'s avatar');

  // A signs; B sees A's avatar sign, and the host turns to A.
  await a.page.click('#text', { clickCount: 3 });
  await a.page.keyboard.type('Hello, my name is Anna. How are you today? My mother lives in a big house near the school. My father works in the library, and my brother goes to the school every morning.');
  await a.page.keyboard.press('Enter');
  const seenByB = await wristTravel(b, a.id);
  console.log(`B sees A's right wrist move ${(seenByB * 100).toFixed(1)} cm`);
  check(seenByB > 0.10, 'B sees A\'s avatar sign (wrist moves > 10 cm)');
  await b.page.waitForFunction((id) => window.gesturaRoom.figures.get('host')?.lookAt === id, { timeout: 30000, polling: 100 }, a.id)
    .then(() => check(true, 'the host looks at A while A signs'), () => check(false, 'the host looks at A while A signs'));
  // It looks at A once it has walked there: its root stands away from its place, in front of A.
  const walked = await b.page.evaluate(() => {
    const r = window.gesturaRoom, p = r.jointPosition('host', 'humanoid_root'), home = r.welcome.host.position;
    return Math.hypot(p[0] - home[0], p[2] - home[2]);
  });
  console.log(`the host's root is ${walked.toFixed(2)} m from its place`);
  check(walked > 0.5, 'the host walked toward A (root > 0.5 m from its place)');

  // A late joiner while A still signs: sees both avatars and A's sentence playing.
  const c = await enter(late);
  const state = await c.page.evaluate(() => [...window.gesturaRoom.figures.keys()]);
  check(state.includes(a.id) && state.includes(b.id) && state.includes('host'), `the late joiner sees A, B and the host (${state.join(', ')})`);
  const welcomeC = await c.page.evaluate(() => window.gesturaRoom.welcome);
  const aPlaying = welcomeC.playing.find((p) => p.participant === a.id);
  console.log(`late joiner's welcome: ${welcomeC.participants.length} participants, A playing ${aPlaying ? `since ${(welcomeC.time - aPlaying.start).toFixed(2)} s` : 'no'}`);
  check(aPlaying && welcomeC.time > aPlaying.start, 'the late joiner is told what A is signing and since when');
  const lateTravel = await wristTravel(c, a.id, 3);
  console.log(`C (late) sees A's right wrist move ${(lateTravel * 100).toFixed(1)} cm mid-sentence`);
  check(lateTravel > 0.10, 'the late joiner sees A sign from mid-sentence');

  // B signs; A (and C) see B's avatar sign.
  await b.page.click('#text', { clickCount: 3 });
  await b.page.keyboard.type('Thank you, see you tomorrow.');
  await b.page.keyboard.press('Enter');
  const [seenByA, seenByC] = await Promise.all([wristTravel(a, b.id), wristTravel(c, b.id)]);
  console.log(`A sees B's right wrist move ${(seenByA * 100).toFixed(1)} cm`);
  check(seenByA > 0.10, 'A sees B\'s avatar sign (wrist moves > 10 cm)');
  console.log(`C (late) sees B's right wrist move ${(seenByC * 100).toFixed(1)} cm`);
  check(seenByC > 0.10, 'the late joiner sees B sign');

  // In step: A and C show B's clip at the same clip time (within 0.15 s).
  const times = await Promise.all([a, c].map((x) => x.page.evaluate((id) => {
    const r = window.gesturaRoom, f = r.figures.get(id);
    return f?.clip ? r.serverNow() - f.clip.start : null;
  }, b.id)));
  console.log(`clip time of B's sentence: A ${times[0]?.toFixed(3)} s, C ${times[1]?.toFixed(3)} s`);

  if (options.out) {
    mkdirSync(options.out, { recursive: true });
      await a.page.screenshot({ path: join(options.out, 'room-a.png') });
      await c.page.screenshot({ path: join(options.out, 'room-c.png') });
  }

  // Malformed input from a page does not hurt the room.
  await a.page.evaluate(() => window.gesturaRoom.ws.send('{not json'));
  await a.page.waitForFunction(() => document.getElementById('status').classList.contains('error'), { timeout: 10000, polling: 100 });
  check(true, 'malformed JSON gets an error the page shows');

  // Leaving: the others see the avatar go.
  await c.page.click('#leave-button');
  await a.page.waitForFunction((id) => !window.gesturaRoom.figures.has(id), { timeout: 10000, polling: 100 }, c.id);
  check(true, 'A sees the late joiner leave');

  for (const x of [a, b, c]) {
    const real = x.errors;
    for (const e of real) console.log(`${x.name}: ${e}`);
    check(real.length === 0, `no console errors for ${x.name}`);
  }
} finally {
  for (const browser of browsers) await browser.close();
  server.stop();
}
process.exit(failed() ? 1 : 0);
