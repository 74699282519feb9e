// What the load runs (tools/serve-load.mjs, tools/room-load.mjs) share: reading their flags,
// starting `gestura serve` on a free loopback port with a throwaway --data folder, warming it, its
// peak RSS, stopping it, and the quantiles they print.
import { spawn } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

// Flags --NAME VALUE for the keys of `defaults` (numbers, except --gestura: a path); exits with the
// usage line on an unknown or incomplete flag, or without --gestura.
export function parseFlags(defaults, usage) {
  const opt = { gestura: null, ...defaults };
  const argv = process.argv.slice(2);
  for (let i = 0; i < argv.length; ++i) {
    const key = argv[i].replace(/^--/, '');
    if (!(key in opt) || i + 1 >= argv.length) { console.error(`unknown or incomplete flag ${argv[i]}`); process.exit(2); }
    opt[key] = key === 'gestura' ? argv[++i] : Number(argv[++i]);
  }
  if (!opt.gestura) { console.error(`usage: ${usage}`); process.exit(2); }
  return opt;
}

// Starts the server and waits for its address; the first sentence is signed before returning (it
// builds the avatar and the signer), as on a server that has run a while.
export async function startServer({ gestura, threads }, prefix = 'gestura-load-') {
  const data = mkdtempSync(join(tmpdir(), prefix));
  const server = spawn(gestura, ['serve', '--port', '0', '--data', data, '--threads', String(threads), '--max-connections', '1000'],
    { stdio: ['ignore', 'pipe', 'inherit'] });
  const url = await new Promise((resolve, reject) => {
    let text = '';
    server.stdout.on('data', (c) => { text += c; const m = text.match(/listening on (http:\/\/[^/\s]+)\//); if (m) resolve(m[1]); });
    server.on('exit', (code) => reject(new Error(`server exited ${code}`)));
  });
  server.on('exit', (code, signal) => { if (code !== 0 && signal !== 'SIGTERM') console.error(`gestura serve died: code ${code}, signal ${signal}`); });
  const peakRss = () => Number(readFileSync(`/proc/${server.pid}/status`, 'utf8').match(/VmHWM:\s+(\d+)/)[1]) / 1024;
  await fetch(`${url}/api/say`, { method: 'POST', headers: { 'Content-Type': 'application/json' }, body: '{"text":"hello"}' });
  const rssWarm = peakRss();
  // Whether it still answers, its peak RSS; then stopped and its data folder removed.
  const stop = async () => {
    const alive = await fetch(`${url}/health`).then((r) => r.status).catch(() => 'down');
    const rssPeak = peakRss();
    server.kill('SIGTERM');
    rmSync(data, { recursive: true, force: true });
    return { alive, rssPeak };
  };
  return { server, url, port: Number(new URL(url).port), rssWarm, stop };
}

// The p-quantile of a sorted array (NaN when empty).
export const quantile = (a, p) => (a.length ? a[Math.min(a.length - 1, Math.floor(p * a.length))] : NaN);
