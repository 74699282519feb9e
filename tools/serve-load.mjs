// A bounded load run of `gestura serve` on the loopback (make load; not a test): N concurrent
// clients POST /api/say?format=glb with everyday sentences for D seconds, while a few slow clients
// dribble a request byte by byte and others send oversized or malformed bodies. Prints p50/p90/p99
// latency of the good requests, errors, the abusers' statuses, /health latency under load and the
// server's peak RSS.
//   node tools/serve-load.mjs --gestura build/bin/gestura [--clients 200] [--seconds 60] [--threads 2]
import { connect } from 'node:net';
import { parseFlags, quantile as q, startServer } from './load-common.mjs';

const opt = parseFlags({ clients: 200, seconds: 60, threads: 2 }, 'node tools/serve-load.mjs --gestura path/to/gestura [--clients N] [--seconds S] [--threads T]');

const sentences = [
  'Hello, how are you?', 'My name is Anna.', 'Where is the train station?', 'I like coffee in the morning.',
  'Do you want to eat with us tonight?', 'The weather is cold today.', 'Thank you very much!', 'I do not understand.',
  'Can you help me, please?', 'We live in a small house near the river.', 'What time is it?', 'My brother works at the hospital.',
];

const { url, port, rssWarm, stop } = await startServer(opt);

const latencies = [], statuses = new Map(), abuse = new Map(), health = [];
let bytes = 0;
const count = (map, key) => map.set(key, (map.get(key) ?? 0) + 1);
const end = Date.now() + opt.seconds * 1000;

async function client(i) {
  let n = i;
  while (Date.now() < end) {
    const text = sentences[n++ % sentences.length];
    const t0 = performance.now();
    try {
      const r = await fetch(`${url}/api/say?format=glb`, { method: 'POST', headers: { 'Content-Type': 'application/json', 'Accept-Encoding': 'gzip' },
        body: JSON.stringify({ text }) });
      const body = await r.arrayBuffer();
      count(statuses, r.status);
      if (r.status === 200) { latencies.push(performance.now() - t0); bytes += body.byteLength; }
    } catch (e) {
      count(statuses, `network: ${e.cause?.code ?? e.message}`);
    }
  }
}

// Slow clients: one byte of a request every 500 ms; the server's 10 s read limit must cut them off.
function slowClient() {
  return new Promise((resolve) => {
    const socket = connect(port, '127.0.0.1');
    const request = 'POST /api/say HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: 20\r\n\r\n{"text":"hello"}   ';
    let k = 0;
    const started = Date.now();
    const timer = setInterval(() => { if (k < request.length && !socket.destroyed) socket.write(request[k++]); }, 500);
    socket.on('data', () => {});
    socket.on('close', () => { clearInterval(timer); count(abuse, `slow client cut after ${Math.round((Date.now() - started) / 1000)} s`); resolve(); });
    socket.on('error', () => {});
    setTimeout(() => socket.destroy(), opt.seconds * 1000 + 5000);
  });
}

async function abuser() {
  const bad = [
    ['oversized', JSON.stringify({ text: 'a'.repeat(100000) })],
    ['malformed', '{"text": '],
    ['binary', Buffer.from(Array.from({ length: 3000 }, (_, k) => (k * 7919) % 256))],
    ['unknown field', '{"text":"hi","output":"/etc/x"}'],
  ];
  let k = 0;
  while (Date.now() < end) {
    const [name, body] = bad[k++ % bad.length];
    try {
      const r = await fetch(`${url}/api/say`, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body });
      await r.arrayBuffer();
      count(abuse, `${name} → ${r.status}`);
    } catch (e) {
      count(abuse, `${name} → ${e.cause?.code ?? e.message}`);
    }
    await new Promise((r) => setTimeout(r, 200));
  }
}

async function healthProbe() {
  while (Date.now() < end) {
    const t0 = performance.now();
    try { const r = await fetch(`${url}/health`); await r.text(); health.push(performance.now() - t0); } catch { health.push(Infinity); }
    await new Promise((r) => setTimeout(r, 500));
  }
}

const started = Date.now();
await Promise.all([...Array(opt.clients).keys()].map(client).concat([slowClient(), slowClient(), slowClient(), abuser(), healthProbe()]));
const seconds = (Date.now() - started) / 1000;
const { alive, rssPeak } = await stop();

latencies.sort((a, b) => a - b);
health.sort((a, b) => a - b);
const errors = [...statuses].filter(([s]) => s !== 200).reduce((n, [, c]) => n + c, 0);
console.log(`clients ${opt.clients}, ${seconds.toFixed(0)} s, server threads ${opt.threads}`);
console.log(`say: ${latencies.length} answered (${(latencies.length / seconds).toFixed(1)}/s), errors ${errors}`);
console.log(`latency p50 ${q(latencies, 0.5).toFixed(0)} ms, p90 ${q(latencies, 0.9).toFixed(0)} ms, p99 ${q(latencies, 0.99).toFixed(0)} ms, max ${q(latencies, 1).toFixed(0)} ms`);
console.log(`mean clip ${(bytes / Math.max(1, latencies.length) / 1024).toFixed(1)} KB decoded (sent gzip)`);
console.log(`statuses: ${JSON.stringify(Object.fromEntries(statuses))}`);
console.log(`abuse: ${JSON.stringify(Object.fromEntries(abuse))}`);
console.log(`/health under load: p50 ${q(health, 0.5).toFixed(0)} ms, max ${q(health, 1).toFixed(0)} ms`);
console.log(`server peak RSS: ${rssWarm.toFixed(0)} MB after warm-up, ${rssPeak.toFixed(0)} MB at the end; alive after: ${alive}`);
process.exit(alive === 200 ? 0 : 1);
