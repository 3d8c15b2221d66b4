// bench.mjs: the browser build's figures (a benchmark, not a test; `make bench` runs it after
// frame_bench). Per lesson page, in headless Chromium (WebGL2 through SwiftShader) from a local server:
//   - its download: wasm + data + js, gzip -9;
//   - the time from navigation to its first frame, in the page as a student opens it (a window the
//     size of the view, the frame budget on);
//   - its frame time at full size (the page's headless mode: no budget), the median of frames 2-11,
//     beside the same lesson's native frame time from frame_bench's CSV of the same `make bench`;
//   - the frames per second the page holds with the frame budget on, and the render scale the budget
//     settled on (the median frame of the run's second half, the last frame's scale).
// Per deck of the site's slides: the time from opening the deck at its first live slide to that
// slide's first live frame (the median of three openings), at 1280x720.
// Every figure comes from the lesson's own --bench CSV (written into the page's file system), whose
// frame time in the browser is the time between frames. With --markdown FILE the table replaces the
// section "## In the browser" of FILE (appended when FILE has none).
//   node tools/wasm/bench.mjs --site build/web/site [--size 1280x720] [--native out/bench/frames.csv]
//                             [--markdown docs/benchmarks.md] [--window-frames 60]
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { launchChromium } from '../web/check-page.mjs';
import { liveFrames, liveSlides, siteDecks } from './decks.mjs';
import { serveSite } from './site_server.mjs';

const opts = { site: 'build/web/site', size: '1280x720', native: '', markdown: '', 'window-frames': '60' };
for (let i = 2; i < process.argv.length; i += 2) {
  const key = process.argv[i].replace(/^--/, '');
  if (!(key in opts) || process.argv[i + 1] === undefined) {
    console.error(`bench.mjs: bad option ${process.argv[i]}; valid: ${Object.keys(opts).map((k) => '--' + k).join(' ')}`);
    process.exit(2);
  }
  opts[key] = process.argv[i + 1];
}
const root = path.resolve(opts.site);
const pages = fs.existsSync(root) ? fs.readdirSync(root).filter((f) => /^lesson_.*\.html$/.test(f)).sort() : [];
if (pages.length === 0) {
  console.error(`bench.mjs: no lesson pages in ${root} (make web builds them)`);
  process.exit(2);
}

// frame_bench's CSV: lesson,preset,size,frame_ms,floor_ms,ratio_to_floor,draw_calls,window_fps,window_render_scale
const native = new Map();
if (opts.native && fs.existsSync(opts.native)) {
  for (const line of fs.readFileSync(opts.native, 'utf8').split('\n').slice(1)) {
    const c = line.split(',');
    if (c[1] === 'default') native.set(c[0], { ms: Number(c[3]), fps: c[7], scale: c[8] });
  }
}

const median = (v) => [...v].sort((a, b) => a - b)[Math.floor(v.length / 2)];
// The lesson's --bench CSV: frame,...,ms (column 4),draw calls,render scale (column 6).
function frames(csv) {
  return csv.trim().split('\n').slice(1).map((l) => l.split(',')).map((c) => ({ frame: Number(c[0]), ms: Number(c[4]), scale: Number(c[6]) }));
}

const server = await serveSite(root);
const browser = await launchChromium();
const [w, h] = opts.size.split('x').map(Number);
const base = `http://127.0.0.1:${server.address().port}`;
// One run of the page; resolves with its first frame's time and its --bench CSV.
async function run(page, query) {
  const p = await browser.newPage({ viewport: { width: w, height: h } });
  await p.goto(`${base}/${page}?size=${opts.size}&bench=/bench.csv&${query}`);
  await p.waitForFunction(() => window.shadowlab && window.shadowlab.exit !== undefined, null, { timeout: 900000 });
  const r = await p.evaluate(() => ({
    exit: window.shadowlab.exit,
    first: window.shadowlab.firstFrameMs,
    csv: new TextDecoder().decode(window.FS.readFile('/bench.csv')),
  }));
  await p.close();
  if (r.exit !== 0) throw new Error(`${page}?${query}: the lesson exited ${r.exit}`);
  return { first: r.first, frames: frames(r.csv) };
}

const rows = [];
for (const page of pages) {
  const stem = page.replace(/\.html$/, ''), lesson = stem.replace(/^lesson_/, '');
  const gz = ['.wasm', '.data', '.js'].reduce((sum, ext) =>
    sum + zlib.gzipSync(fs.readFileSync(path.join(root, stem + ext)), { level: 9 }).length, 0);
  const full = await run(page, 'headless&frames=12');
  const fullMs = median(full.frames.filter((f) => f.frame >= 2).map((f) => f.ms));
  const n = Number(opts['window-frames']);
  const windowed = await run(page, `frames=${n}`);
  const late = windowed.frames.filter((f) => f.frame >= n / 2);
  const fps = 1000 / median(late.map((f) => f.ms));
  const nat = native.get(lesson);
  rows.push(`| ${lesson} | ${(gz / 1048576).toFixed(2)} MB | ${(windowed.first / 1000).toFixed(2)} s | ${fullMs.toFixed(1)} | ` +
            `${nat ? nat.ms.toFixed(1) : ''} | ${nat ? (fullMs / nat.ms).toFixed(1) + 'x' : ''} | ` +
            `${fps.toFixed(1)} (${late.at(-1).scale.toFixed(2)}) | ${nat && nat.fps ? `${nat.fps} (${nat.scale})` : ''} |`);
  console.error(rows.at(-1));
}
// The decks: opening at the first live slide, to its first live frame.
const deckRows = [];
for (const deck of siteDecks(root)) {
  const times = [];
  for (let k = 0; k < 3; ++k) {
    const p = await browser.newPage({ viewport: { width: 1280, height: 720 } });
    await p.goto(`${base}/slides/${deck}#/0`);
    await p.waitForFunction(() => window.Reveal && Reveal.isReady());
    const live = await liveSlides(p);
    await p.close();
    if (!live.length) break;
    const q = await browser.newPage({ viewport: { width: 1280, height: 720 } });
    await q.goto(`${base}/slides/${deck}#/${live[0][0]}`);
    times.push(await liveFrames(q, live[0][1], 1));
    await q.close();
  }
  if (times.length) deckRows.push(`| ${deck.replace(/\.html$/, '')} | ${(median(times) / 1000).toFixed(2)} s |`);
  if (times.length) console.error(deckRows.at(-1));
}
await browser.close();
server.close();

const section = `## In the browser

Generated by \`make bench\` (\`tools/wasm/bench.mjs\`): each lesson's page (\`make web\`) in Debian's headless
Chromium, WebGL2 through its software renderer (SwiftShader), served from this machine, at ${opts.size}. Download:
the page's wasm, data and js, gzip -9. First frame: from navigation to the first frame drawn. Frame ms: the page's
headless mode (full size, no frame budget), the median of frames 2-11, beside the native lesson's on llvmpipe from
the table above. Page fps: the page as a student opens it, the frame budget on: the median frame of the second half of
${opts['window-frames']} frames, and the render scale it settled on. Goals: under 4 MB, a first frame under 3 s, 15 fps.

| lesson | download (gzip) | first frame | frame ms, browser | frame ms, native | ratio | page fps (render scale) | native window fps (render scale) |
|---|---|---|---|---|---|---|---|
${rows.join('\n')}

The decks (\`make web\` puts them in the site): the time from opening a deck at its first live slide to that
slide's first live frame, the median of three openings, at 1280x720.

| deck | first live frame |
|---|---|
${deckRows.join('\n')}
`;
console.log(section);
if (opts.markdown) {
  const text = fs.existsSync(opts.markdown) ? fs.readFileSync(opts.markdown, 'utf8') : '';
  const at = text.indexOf('\n## In the browser\n');
  fs.writeFileSync(opts.markdown, (at >= 0 ? text.slice(0, at + 1) : text.replace(/\n*$/, '\n\n')) + section);
}
