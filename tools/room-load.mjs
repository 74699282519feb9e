// A bounded load run of the shared rooms on the loopback (make load-rooms; not a test): N room
// clients in rooms of up to 8 seats for D seconds. Every client pings once a second and signs a
// sentence every few seconds; some also drive their avatar with 10 landmarks messages a second.
// Prints the messages a second the server sent and took, p50/p99 of the play latency (a `say`
// sent → the `play` arriving at each other participant of its room: the whole path of signing the
// sentence, making its clip and broadcasting it), poses a second, errors by code, the server's
// peak RSS and whether it still answers.
//   node --experimental-websocket tools/room-load.mjs --gestura build/bin/gestura [--clients 40] [--seconds 30] [--capture 8] [--threads 2]
import { parseFlags, quantile as q, startServer } from './load-common.mjs';

if (typeof WebSocket === 'undefined') { console.error('run with node --experimental-websocket (node 20) or node ≥ 22'); process.exit(2); }
const opt = parseFlags({ clients: 40, seconds: 30, capture: 8, threads: 2, every: 6 },
  'node --experimental-websocket tools/room-load.mjs --gestura path/to/gestura [--clients N] [--seconds S] [--capture K] [--threads T] [--every S]');
if (!(opt.clients >= 1 && opt.clients <= 512 && opt.seconds >= 1 && opt.seconds <= 600)) { console.error('clients 1–512, seconds 1–600'); process.exit(2); }

const sentences = ['Hello, how are you?', 'My name is Anna.', 'Thank you very much!', 'What time is it?', 'I like coffee.',
                   'Where is the school?', 'See you tomorrow.', 'My mother lives in a big house.'];
const { url, rssWarm, stop } = await startServer(opt, 'gestura-room-load-');

// A landmarks frame: a person facing the camera, the right forearm swinging with `phase`.
function frame(phase) {
  const pose = Array.from({ length: 33 }, () => [0.5, 0.5, 0, 0.9]);
  const set = (i, x, y, z) => { pose[i] = [+x.toFixed(4), +y.toFixed(4), +z.toFixed(4), 0.95]; };
  set(7, 0.54, 0.2, 0); set(8, 0.46, 0.2, 0); set(11, 0.6, 0.35, 0); set(12, 0.4, 0.35, 0);
  set(13, 0.63, 0.55, 0); set(15, 0.64, 0.75, 0); set(14, 0.33, 0.5, -0.1);
  set(16, 0.36 + 0.05 * Math.sin(phase), 0.3 + 0.1 * Math.cos(phase), -0.2); set(23, 0.56, 0.8, 0); set(24, 0.44, 0.8, 0);
  return JSON.stringify({ type: 'landmarks', pose, aspect: 1.3333 });
}

const said = new Map();  // "room/participant/text#n" → send time (ms)
const latencies = [], errors = new Map();
let received = 0, sent = 0, poses = 0, plays = 0, closed = 0;
const count = (map, key) => map.set(key, (map.get(key) ?? 0) + 1);
const end = Date.now() + opt.seconds * 1000;
const rooms = Math.ceil(opt.clients / 8);

function client(i) {
  const room = `load-${i % rooms}`;
  return new Promise((resolve) => {
    const ws = new WebSocket(`${url.replace('http', 'ws')}/ws/room/${room}`);
    const timers = [];
    let me = null, n = 0, phase = 0;
    const send = (m) => { if (ws.readyState === WebSocket.OPEN) { ws.send(typeof m === 'string' ? m : JSON.stringify(m)); sent += 1; } };
    const finish = () => { timers.forEach(clearInterval); try { ws.close(); } catch { /* gone */ } resolve(); };
    ws.onopen = () => send({ type: 'join', name: `L${i}` });
    ws.onmessage = (e) => {
      received += 1;
      const m = JSON.parse(e.data);
      if (m.type === 'welcome') {
        me = m.you.id;
        timers.push(setInterval(() => send({ type: 'ping', t: performance.now() / 1000 }), 1000));
        // Sentences spread over the run: a client's first after a random share of the interval.
        setTimeout(() => {
          const say = () => { const text = `${sentences[(i + n) % sentences.length]}`; said.set(`${room}/${me}/${text}`, Date.now()); n += 1; send({ type: 'say', text }); };
          say();
          timers.push(setInterval(say, opt.every * 1000));
        }, Math.random() * opt.every * 1000);
        if (i < opt.capture) timers.push(setInterval(() => send(frame(phase += 0.3)), 100));
      } else if (m.type === 'play') {
        plays += 1;
        const t0 = said.get(`${room}/${m.participant}/${m.text}`);
        if (t0 !== undefined && m.participant !== me) latencies.push(Date.now() - t0);
      } else if (m.type === 'pose') poses += 1;
      else if (m.type === 'error') count(errors, `${m.error.code} ${m.error.field ?? ''}`.trim());
    };
    ws.onclose = () => { closed += Date.now() < end ? 1 : 0; finish(); };
    ws.onerror = () => {};
    setTimeout(finish, Math.max(0, end - Date.now()));
  });
}

const started = Date.now();
await Promise.all(Array.from({ length: opt.clients }, (_, i) => client(i)));
const seconds = (Date.now() - started) / 1000;
const { alive, rssPeak } = await stop();
latencies.sort((a, b) => a - b);
console.log(`${opt.clients} room clients in ${rooms} rooms for ${seconds.toFixed(1)} s (${opt.capture} driving their avatar at 10 frames/s), --threads ${opt.threads}`);
console.log(`messages: ${(received / seconds).toFixed(0)}/s from the server, ${(sent / seconds).toFixed(0)}/s to it`);
console.log(`play latency (say → play at the others; signing included): p50 ${q(latencies, 0.5).toFixed(0)} ms, p99 ${q(latencies, 0.99).toFixed(0)} ms over ${latencies.length} deliveries (${plays} plays received)`);
console.log(`poses: ${(poses / seconds).toFixed(0)}/s received`);
console.log(`errors: ${errors.size ? [...errors].map(([k, c]) => `${k} ×${c}`).join(', ') : 'none'}; connections closed early: ${closed}`);
console.log(`server RSS: ${rssWarm.toFixed(0)} MB warm, peak ${rssPeak.toFixed(0)} MB; /health after the run: ${alive}`);
process.exit(alive === 200 ? 0 : 1);
