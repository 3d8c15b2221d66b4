// bench.mjs: the browser build's figures (a benchmark, not a test): per lesson page, its download
// (wasm + data + js, gzip -9), the time from navigation to its first frame in headless Chromium
// from a local server, and its frame time at a size (median of frames 20-80).
//   node tools/wasm/bench.mjs --site build/web/site [--size 1280x720] [--frames 80]
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { launchChromium } from '../web/check-page.mjs';
import { serveSite } from './site_server.mjs';

const opts = { site: 'build/web/site', size: '1280x720', frames: '80' };
for (let i = 2; i < process.argv.length; i += 2) opts[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
const root = path.resolve(opts.site);
const server = await serveSite(root);
const browser = await launchChromium();
const [w, h] = opts.size.split('x').map(Number);
const rows = [];
for (const page of fs.readdirSync(root).filter((f) => /^lesson_.*\.html$/.test(f)).sort()) {
  const stem = page.replace(/\.html$/, '');
  const gz = ['.wasm', '.data', '.js'].reduce((sum, ext) =>
    sum + zlib.gzipSync(fs.readFileSync(path.join(root, stem + ext)), { level: 9 }).length, 0);
  const p = await browser.newPage({ viewport: { width: w, height: h } });
  await p.goto(`http://127.0.0.1:${server.address().port}/${page}?size=${opts.size}`);
  const n = Number(opts.frames);
  await p.waitForFunction((n) => (window.shadowlab.frameTimes || []).length >= n, n, { timeout: 600000 });
  const t = await p.evaluate(() => ({ first: window.shadowlab.firstFrameMs, times: window.shadowlab.frameTimes }));
  await p.close();
  const steps = t.times.slice(20, n).map((x, i, a) => (i ? x - a[i - 1] : null)).filter((x) => x !== null).sort((a, b) => a - b);
  const median = steps[Math.floor(steps.length / 2)];
  rows.push(`| ${stem.replace(/^lesson_/, '')} | ${(gz / 1048576).toFixed(2)} MB | ${(t.first / 1000).toFixed(2)} s | ${median.toFixed(1)} ms |`);
  console.error(rows.at(-1));
}
await browser.close();
server.close();
console.log(`| lesson | download (gzip) | first frame | frame at ${opts.size} |\n|---|---|---|---|\n${rows.join('\n')}`);
