// Shared by the browser tests: start `gestura serve` on a free port with this web/ folder, and
// headless chromium driven by puppeteer-core. Exit code 77 (ctest: skipped) only when chromium or
// node is truly absent; everything else missing is a failure.
import { spawn } from 'node:child_process';
import { existsSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

export const webRoot = resolve(dirname(fileURLToPath(import.meta.url)), '..');

export function findChromium() {
  for (const p of [process.env.CHROMIUM, '/usr/bin/chromium', '/usr/bin/chromium-browser'])
    if (p && existsSync(p)) return p;
  return null;
}

export function args() {
  const out = { gestura: null, out: null };
  const a = process.argv.slice(2);
  for (let i = 0; i < a.length; ++i) {
    if (a[i] === '--gestura') out.gestura = a[++i];
    else if (a[i] === '--out') out.out = a[++i];
    else throw new Error(`unknown argument ${a[i]}`);
  }
  if (!out.gestura) throw new Error('usage: node TEST.mjs --gestura path/to/gestura [--out DIR]');
  return out;
}

// Resolves {url, stop()} once the server prints its address.
export function startServer(gestura, extra = []) {
  const data = mkdtempSync(join(tmpdir(), 'gestura-web-test-'));
  const child = spawn(gestura, ['serve', '--port', '0', '--web', webRoot, '--data', data, ...extra], { stdio: ['ignore', 'pipe', 'inherit'] });
  return new Promise((resolvePromise, reject) => {
    let text = '';
    child.stdout.on('data', (chunk) => {
      text += chunk;
      const m = text.match(/listening on (http:\/\/[^/\s]+)\//);
      if (m) resolvePromise({
        url: m[1],
        stop: () => { child.kill('SIGTERM'); rmSync(data, { recursive: true, force: true }); },
      });
    });
    child.on('exit', (code) => reject(new Error(`gestura serve exited with ${code}: ${text}`)));
  });
}

export async function launchBrowser(chromium, extraArgs = []) {
  const { default: puppeteer } = await import('puppeteer-core');
  return puppeteer.launch({
    executablePath: chromium, headless: true,
    args: ['--no-sandbox', '--disable-dev-shm-usage', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
           '--disable-background-networking', '--disable-component-update', '--no-first-run', ...extraArgs],
  });
}

// Collects console errors and page errors of a page.
export function watchErrors(page) {
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => errors.push(`page: ${e.message}`));
  page.on('requestfailed', (r) => errors.push(`request failed: ${r.url()} ${r.failure()?.errorText}`));
  return errors;
}

let failures = 0;
export function check(ok, what) {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failures += 1;
}
export function failed() { return failures; }

export function skipUnlessBrowser() {
  const chromium = findChromium();
  if (!chromium) {
    console.log('SKIP: no chromium (install the Debian package chromium)');
    process.exit(77);
  }
  return chromium;
}
