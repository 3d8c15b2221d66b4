// check.mjs: a lesson's browser page against the same lesson built natively, in headless Chromium
// (playwright-core, tools/web). The web tests (tests/web.cmake) run it once per lesson.
//
//   node tools/wasm/check.mjs --site build/web/site --bin build/default/bin --lesson 03_shadow_quality
//        [--presets a,b:8,c] [--size 320x180] [--out DIR] [--bound 1.0] [--levels 8]
//
// For the default view and each preset: the page runs headless (`?headless&frames=2&size=...`,
// the lesson's own --screenshot into the page's file system) and the native lesson renders the same
// view; the two pictures are compared, and the share of pixels whose largest channel differs by
// more than --levels must stay at or below --bound percent. Every page must log no WebGL error
// (Chromium's "WebGL:" warnings, the lesson's "GL error" lines) and exit 0. Then the lesson's
// hotkeys pressed on the page must change the parameters they name, "copy link" must give a URL
// that opens the same view (a dragged camera included), the canvas must follow the window, a URL with a bad
// parameter must show the lesson's error on the page and go on at the defaults, and a browser
// without WebGL2 must get the page's message instead of a black canvas.
// Exit status: 0 all held, 1 any failed (each failure one line), 2 bad usage.
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { launchChromium } from '../web/check-page.mjs';
import { comparePngs, webglError } from './compare.mjs';
import { serveSite } from './site_server.mjs';

const args = { size: '320x180', bound: '1.0', levels: '8', presets: '', out: '' };
for (let i = 2; i < process.argv.length; i += 2) {
  const key = process.argv[i].replace(/^--/, '');
  if (!(key in args) && !['site', 'bin', 'lesson'].includes(key)) usage(`unknown option ${process.argv[i]}`);
  args[key] = process.argv[i + 1];
}
function usage(why) {
  console.error(`check.mjs: ${why}\nusage: node tools/wasm/check.mjs --site DIR --bin DIR --lesson NN_name ` +
                '[--presets a,b,c] [--size WxH] [--out DIR] [--bound PERCENT] [--levels N]');
  process.exit(2);
}
if (!args.site || !args.bin || !args.lesson) usage('--site, --bin and --lesson are required');
const page = `lesson_${args.lesson}.html`;
if (!fs.existsSync(path.join(args.site, page))) usage(`${args.site}/${page} missing: make web builds it`);
const native = path.join(args.bin, `lesson_${args.lesson}`);
if (!fs.existsSync(native)) usage(`${native} missing: make build builds it`);
const out = args.out || fs.mkdtempSync('/tmp/shadowlab-web-');
fs.mkdirSync(out, { recursive: true });

const server = await serveSite(args.site);
const base = `http://127.0.0.1:${server.address().port}/${page}`;

const failures = [];
const fail = (what) => { failures.push(what); console.log(`FAIL ${what}`); };
const browser = await launchChromium();

// Opens `url`, collecting console errors; resolves when the lesson's run ends (or after `ms`).
async function open(url, { ms = 90000, init } = {}) {
  const p = await browser.newPage({ viewport: { width: 800, height: 450 } });
  const errors = [];
  p.on('console', (m) => {
    if (webglError(m.text())) errors.push(m.text());
  });
  p.on('pageerror', (e) => errors.push('page error: ' + e.message));
  if (init) await p.addInitScript(init);
  await p.goto(url);
  return { p, errors };
}
async function waitExit(p, ms) {
  await p.waitForFunction(() => window.shadowlab && window.shadowlab.exit !== undefined, null, { timeout: ms });
  return p.evaluate(() => window.shadowlab.exit);
}

// A parameter's value in the page's lesson, as --set takes it (shadowlab_param).
const param = (p, name) => p.evaluate((n) => window.Module.ccall('shadowlab_param', 'string', ['string'], [n]), name);

// Waits (up to 10 s) for the lesson's next frames to take an input: `name` no longer `before`. A page
// under load draws a frame a second or slower, so a fixed wait passed or failed by chance.
async function changed(p, name, before) {
  await p.waitForFunction(([n, b]) => window.Module.ccall('shadowlab_param', 'string', ['string'], [n]) !== b,
                          [name, before], { timeout: 10000 }).catch(() => {});
}

// --presets a,b:8: a view's own bound after a colon, for pictures the two rasterisers may draw
// differently by nature (acne's stripes, nearest-filtered moire: the tests say why).
const views = ['', ...args.presets.split(',').filter(Boolean)];
for (const view of views) {
  const [preset, ownBound] = view.split(':');
  const bound = ownBound !== undefined ? Number(ownBound) : Number(args.bound);
  const name = preset || 'default';
  const nativePng = path.join(out, `${name}.native.png`), webPng = path.join(out, `${name}.web.png`);
  const cli = ['--headless', '--frames', '2', '--size', args.size, '--screenshot', nativePng];
  if (preset) cli.push('--preset', preset);
  const run = spawnSync(native, cli, { encoding: 'utf8', timeout: 120000 });
  if (run.status !== 0) { fail(`${name}: the native lesson exited ${run.status}: ${run.stderr.trim()}`); continue; }
  const query = `?headless&strict-gl&frames=2&size=${args.size}&screenshot=/shot.png${preset ? '&preset=' + preset : ''}`;
  const { p, errors } = await open(base + query);
  const started = Date.now();
  let code;
  try {
    code = await waitExit(p, 90000);
  } catch {
    fail(`${name}: the page did not finish its 2 frames in 90 s`);
    await p.close();
    continue;
  }
  const seconds = ((Date.now() - started) / 1000).toFixed(1);
  if (code !== 0) fail(`${name}: the page's lesson exited ${code}`);
  for (const e of errors) fail(`${name}: ${e}`);
  const bytes = await p.evaluate(() => { try { return Array.from(window.FS.readFile('/shot.png')); } catch { return null; } });
  if (!bytes) { fail(`${name}: the page wrote no screenshot`); await p.close(); continue; }
  fs.writeFileSync(webPng, Buffer.from(bytes));
  const r = await comparePngs(p, fs.readFileSync(nativePng), fs.readFileSync(webPng), Number(args.levels));
  await p.close();
  if (r.error) { fail(`${name}: ${r.error}`); continue; }
  const ok = r.percent <= bound;
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${name}: ${r.percent.toFixed(3)} % of pixels differ by more than ${args.levels} ` +
              `levels (bound ${bound} %, largest ${r.worst}); page ${seconds} s; ${webPng}`);
  if (!ok) failures.push(`${name}: ${r.percent.toFixed(3)} % over the bound`);
}

// The lesson's hotkeys, pressed on the page (emscripten's GLFW takes the browser's key events):
// each changes the parameter it names (read back with shadowlab_param).
{
  const listed = spawnSync(native, ['--list-hotkeys'], { encoding: 'utf8' }).stdout.split('\n')
    .map((l) => l.trim().split(/\s+/)).filter((f) => f.length >= 2 && /^[A-Z]$/.test(f[0]) && f[1] !== '(framework)');
  const keys = listed.slice(0, 4);
  if (keys.length === 0) console.log('ok   hotkeys: the lesson has no letter hotkeys of its own');
  else {
    const { p, errors } = await open(`${base}?size=${args.size}`);
    try {
      await p.waitForFunction(() => (window.shadowlab.frameTimes || []).length >= 3, null, { timeout: 60000 });
      // The keyboard's focus: a click on the picture's bottom right corner, where no window of the UI
      // is (the canvas's centre at this size is under the header: a click there makes a window the
      // UI's active item, and ImGui then takes the keys of the next two frames, as natively). Three
      // frames pass before the first key.
      const [w, h] = args.size.split('x').map(Number);
      await p.click('#canvas', { position: { x: w - 4, y: h - 4 } });
      const clicked = await p.evaluate(() => window.shadowlab.frameTimes.length);
      await p.waitForFunction((n) => window.shadowlab.frameTimes.length >= n + 3, clicked, { timeout: 60000 });
      for (const [key, name] of keys) {
        const before = await param(p, name);
        await p.keyboard.press(key.toLowerCase());
        await changed(p, name, before);
        const after = await param(p, name);
        if (before === after) fail(`hotkey ${key}: ${name} stayed ${before}`);
        else console.log(`ok   hotkey ${key}: ${name} ${before} -> ${after}`);
      }
      for (const e of errors) fail(`hotkeys: ${e}`);
    } catch (e) {
      fail(`hotkeys: ${e.message.split('\n')[0]}`);
    }
    await p.close();
  }
}

// "copy link" (the panel's button; shadowlab_share is what it calls): after a drag that orbits the
// camera and a hotkey, the page's address holds the view; a new page opened at it has the same
// values. The page without size= fills the window and follows it when the window is resized.
{
  const { p, errors } = await open(base);
  try {
    await p.waitForFunction(() => (window.shadowlab.frameTimes || []).length >= 3, null, { timeout: 60000 });
    const yaw = await param(p, 'camera.yaw');
    await p.mouse.move(480, 330);
    await p.mouse.down();
    await p.mouse.move(600, 310, { steps: 8 });
    await p.mouse.up();
    await changed(p, 'camera.yaw', yaw);
    const status = await p.evaluate(() => window.Module.ccall('shadowlab_share', 'string', [], []));
    const link = new URL(await p.evaluate(() => location.href));
    const sets = link.searchParams.getAll('set');
    if ((await param(p, 'camera.yaw')) === yaw) fail(`copy link: a drag on the canvas left camera.yaw at ${yaw}`);
    else if (!sets.some((s) => s.startsWith('camera.yaw='))) fail(`copy link: the link has no camera.yaw: ${link}`);
    else if (!status.includes(link.href)) fail(`copy link: the status "${status}" does not show the link ${link}`);
    else {
      // What changes by itself (an orbiting light) is left out: read twice, with no input between.
      const names = sets.map((set) => set.slice(0, set.indexOf('=')));
      const values = async (page) => Promise.all(names.map((n) => param(page, n)));
      const first = await values(p);
      await p.waitForTimeout(600);
      const still = (await values(p)).map((v, i) => v === first[i]);
      const again = await open(link.href);
      await again.p.waitForFunction(() => (window.shadowlab.frameTimes || []).length >= 2, null, { timeout: 60000 });
      const linked = await values(again.p);
      const differ = names.map((n, i) => (still[i] && linked[i] !== first[i] ? `${n} ${first[i]} -> ${linked[i]}` : ''))
                          .filter(Boolean);
      if (!still[names.indexOf('camera.yaw')]) fail('copy link: camera.yaw changes by itself: the round trip proves nothing');
      for (const e of again.errors) fail(`copy link: the linked page: ${e}`);
      await again.p.close();
      if (differ.length) fail(`copy link: the linked page differs: ${differ.join(', ')}`);
      else console.log(`ok   copy link: ${sets.length} value(s) (camera included) round trip through ${link.pathname}${link.search.slice(0, 60)}...`);
    }
    await p.setViewportSize({ width: 640, height: 400 });
    await p.waitForTimeout(800);
    const size = await p.evaluate(() => [document.getElementById('canvas').width, document.getElementById('canvas').height]);
    if (size.join('x') !== '640x400') fail(`resize: the window went to 640x400, the canvas stayed ${size.join('x')}`);
    else console.log('ok   resize: the canvas follows the window (800x450 -> 640x400)');
    for (const e of errors) fail(`copy link: ${e}`);
  } catch (e) {
    fail(`copy link: ${e.message.split('\n')[0]}`);
  }
  await p.close();
}

// A bad parameter in the URL: the lesson's own one-line error on the page, then the defaults.
{
  const { p } = await open(`${base}?set=no.such_parameter=1&size=${args.size}`);
  try {
    await p.waitForFunction(() => window.shadowlab && window.shadowlab.retried &&
                                  document.getElementById('message').textContent.length > 0, null, { timeout: 60000 });
    const message = await p.evaluate(() => document.getElementById('message').textContent);
    await p.waitForTimeout(1500);
    const exit = await p.evaluate(() => window.shadowlab.exit);
    if (!/no\.such_parameter/.test(message)) fail(`bad URL: the page's message does not name the parameter: ${message}`);
    else if (exit !== 2) fail(`bad URL: the lesson did not go on at its defaults (exit ${exit})`);
    else console.log(`ok   bad URL: "${message.split('\n')[0]}", then the defaults`);
  } catch {
    fail('bad URL: no message on the page within 60 s');
  }
  await p.close();
}

// No WebGL2 (the browser's context refused): the page's message, never a black canvas.
{
  const init = () => {
    const get = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (kind, ...rest) {
      return kind === 'webgl2' ? null : get.call(this, kind, ...rest);
    };
  };
  const { p } = await open(base, { init });
  await p.waitForTimeout(1500);
  const message = await p.evaluate(() => document.getElementById('message').textContent);
  if (!/WebGL2/.test(message)) fail(`no WebGL2: the page shows no message naming WebGL2 (got "${message}")`);
  else console.log(`ok   no WebGL2: "${message.slice(0, 60)}..."`);
  await p.close();
}

await browser.close();
server.close();
console.log(failures.length ? `check.mjs: ${args.lesson}: ${failures.length} failure(s)` : `check.mjs: ${args.lesson}: all held`);
process.exit(failures.length ? 1 : 0);
