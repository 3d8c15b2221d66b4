// check_slides.mjs: the decks' live figures (live=..., tools/slides) in headless Chromium, from the
// browser build's site, where the decks sit in slides/ beside the lessons' pages.
//
//   node tools/wasm/check_slides.mjs --site build/web/site [--out DIR] [--bound 4] [--levels 24] [--block 8]
//
// Every deck gets at least two live figures. For each slide holding one: the deck turns to it, the
// lesson's page in each live figure must draw three frames with no WebGL error, and the figure
// (the page, as the slide shows it) must match its still (the same box with the page hidden): in
// squares of --block x --block pixels (the two are resampled differently to the slide's scale), at
// most --bound percent of the squares' means may differ by more than --levels. Then the deck turns to the
// next slide: the page must be gone and must have drawn no frame since (a deck runs only the live
// slide on screen). On each deck's first live slide, a drag in the page must turn the lesson's
// camera and PageDown pressed in it must turn the slide. The deck printed for the PDF
// (?print-pdf) must show every still and no page.
// Prints each deck's time from opening (at its first live slide) to that slide's first live frame.
// Exit status: 0 all held, 1 any failed (each failure one line), 2 bad usage.
import fs from 'node:fs';
import path from 'node:path';
import { launchChromium } from '../web/check-page.mjs';
import { comparePngs, webglError } from './compare.mjs';
import { liveFrames, liveSlides, siteDecks } from './decks.mjs';
import { serveSite } from './site_server.mjs';

// The bound as measured (8x8 squares, 24 levels): at most 3.0 % over the twenty live figures, where
// the two rasterisers alias a far checkerboard differently and blend lesson 04's volumes and
// lesson 09's post-projective lines a level apart; a wrong preset or a black page differs in most.
const args = { site: '', out: '', bound: '4', levels: '24', block: '8' };
for (let i = 2; i < process.argv.length; i += 2) {
  const key = process.argv[i].replace(/^--/, '');
  if (!(key in args) || process.argv[i + 1] === undefined) usage(`unknown option or no value: ${process.argv[i]}`);
  args[key] = process.argv[i + 1];
}
function usage(why) {
  console.error(`check_slides.mjs: ${why}\nusage: node tools/wasm/check_slides.mjs --site DIR [--out DIR] [--bound PERCENT] [--levels N] [--block N]`);
  process.exit(2);
}
if (!args.site) usage('--site is required');
const decks = siteDecks(args.site);
if (!decks.length) usage(`${args.site}/slides holds no deck: make web puts them there`);
const out = args.out || fs.mkdtempSync('/tmp/shadowlab-slides-');
fs.mkdirSync(out, { recursive: true });

const failures = [];
const fail = (what) => { failures.push(what); console.log(`FAIL ${what}`); };
const server = await serveSite(args.site);
const base = `http://127.0.0.1:${server.address().port}/slides`;
const browser = await launchChromium();
// The frame budget (on for a software renderer such as this Chromium's) would draw the page at a
// lower resolution than the still: the deck hands its ?set= to every live page.
const query = '?set=budget.mode=off';

async function openDeck(deck, slide, errors) {
  const p = await browser.newPage({ viewport: { width: 1280, height: 720 } });
  p.on('console', (m) => { if (webglError(m.text())) errors.push(m.text()); });
  p.on('pageerror', (e) => errors.push('page error: ' + e.message));
  await p.goto(`${base}/${deck}${query}#/${slide}`);
  await p.waitForFunction(() => window.Reveal && Reveal.isReady(), null, { timeout: 30000 });
  return p;
}

// The first live slide of a deck as a lecturer uses it: a drag in the page turns the lesson's
// camera, and PageDown pressed in the page (a presenter's clicker) turns the slide; back on the
// slide, its page opens again.
async function interact(p, name, index, count) {
  const frame = p.locator('section.present .live iframe').first();
  const yaw = () => frame.evaluate((f) => f.contentWindow.Module.ccall('shadowlab_param', 'string', ['string'], ['camera.yaw']));
  const box = await frame.boundingBox();
  const before = await yaw();
  await p.mouse.move(box.x + box.width * 0.3, box.y + box.height * 0.7);
  await p.mouse.down();
  for (let i = 1; i <= 10; ++i) await p.mouse.move(box.x + box.width * (0.3 + 0.03 * i), box.y + box.height * 0.7);
  await p.mouse.up();
  await p.waitForFunction(([b]) => document.querySelector('section.present .live iframe').contentWindow.Module
    .ccall('shadowlab_param', 'string', ['string'], ['camera.yaw']) !== b, [before], { timeout: 10000 }).catch(() => {});
  const after = await yaw();
  if (after === before) fail(`${name} slide ${index + 1}: a drag in the live page left camera.yaw at ${before}`);
  else console.log(`ok   ${name} slide ${index + 1}: a drag in the live page turned the camera (yaw ${before} -> ${after})`);
  // The drag gave the page the keyboard: PageDown goes to it, not to the deck (the page hands it on).
  if (!(await p.evaluate(() => document.activeElement && document.activeElement.tagName === 'IFRAME')))
    fail(`${name} slide ${index + 1}: the live page did not take the keyboard from a click in it`);
  await p.keyboard.press('PageDown');
  const turned = await p.waitForFunction((i) => Reveal.getIndices().h === i + 1, index, { timeout: 10000 }).then(() => true, () => false);
  if (!turned) fail(`${name} slide ${index + 1}: PageDown in the live page did not turn the slide`);
  else console.log(`ok   ${name} slide ${index + 1}: PageDown in the live page turned the slide`);
  await p.evaluate((i) => Reveal.slide(i), index);
  await liveFrames(p, count);
}

for (const deck of decks) {
  const name = deck.replace(/\.html$/, '');
  const errors = [];
  const probe = await openDeck(deck, 0, errors);
  const live = await liveSlides(probe);
  await probe.close();
  if (live.length < 2) fail(`${name}: ${live.length} live slide(s); every deck shows at least its two most important moments live`);
  let opened = null;
  for (const [index, count] of live) {
    let p = opened;
    const started = Date.now();
    if (!p) p = opened = await openDeck(deck, index, errors);
    else await p.evaluate((i) => Reveal.slide(i), index);
    let first;
    try {
      first = await liveFrames(p, count);
    } catch {
      fail(`${name} slide ${index + 1}: the live figure's page drew no 3 frames in 120 s`);
      continue;
    }
    if (p === opened && index === live[0][0]) console.log(`ok   ${name}: ${(first / 1000).toFixed(2)} s from opening the deck to its first live frame`);
    for (let k = 0; k < count; ++k) {
      // The page's own screenshot of the box's rectangle: an element screenshot waits for the box to
      // hold still over animation frames, which a loaded machine drawing the live page (on the deck's
      // thread: same origin) did not give it within 20 s.
      const box = p.locator('section.present .live').nth(k);
      const rect = await box.evaluate((b) => { const r = b.getBoundingClientRect(); return { x: r.x, y: r.y, width: r.width, height: r.height }; });
      const shot = () => p.screenshot({ clip: rect, timeout: 120000 });
      const livePng = await shot();
      await box.evaluate((b) => { b.querySelector('iframe').style.visibility = 'hidden'; });
      const stillPng = await shot();
      await box.evaluate((b) => { b.querySelector('iframe').style.visibility = ''; });
      const where = `${name} slide ${index + 1} figure ${k + 1}`;
      fs.writeFileSync(path.join(out, `${name}-${index + 1}-${k + 1}.live.png`), livePng);
      fs.writeFileSync(path.join(out, `${name}-${index + 1}-${k + 1}.still.png`), stillPng);
      const r = await comparePngs(p, livePng, stillPng, Number(args.levels), Number(args.block));
      if (r.error) fail(`${where}: ${r.error}`);
      else if (r.percent > Number(args.bound)) fail(`${where}: ${r.percent.toFixed(3)} % of ${args.block}x${args.block} squares differ from the still by more than ${args.levels} levels (bound ${args.bound} %)`);
      else console.log(`ok   ${where}: ${r.percent.toFixed(3)} % of squares differ from the still (bound ${args.bound} %); ${((Date.now() - started) / 1000).toFixed(1)} s`);
    }
    if (p === opened && index === live[0][0]) await interact(p, name, index, count);
    // Leave the slide: its pages go, and draw nothing more.
    // The pages' frame counts are read in the same task as the turn: no frame can come between.
    const before = await p.evaluate((i) => {
      window.__left = [...Reveal.getCurrentSlide().querySelectorAll('.live iframe')].map((f) => f.contentWindow);
      Reveal.slide(i + 1);
      return window.__left.map((w) => w.shadowlab.frameTimes.length);
    }, index);
    await p.waitForTimeout(1500);
    const after = await p.evaluate((i) => ({ pages: Reveal.getSlides()[i].querySelectorAll('iframe').length,
                                            frames: window.__left.map((w) => w.shadowlab.frameTimes.length) }), index);
    if (after.pages) fail(`${name} slide ${index + 1}: ${after.pages} page(s) still in the slide after it was left`);
    else if (after.frames.some((n, i) => n !== before[i])) fail(`${name} slide ${index + 1}: its page drew ${after.frames.map((n, i) => n - before[i])} frame(s) after the slide was left`);
    else console.log(`ok   ${name} slide ${index + 1}: left, its page gone and stopped`);
  }
  if (opened) await opened.close();
  // The PDF's layout: every still, no page.
  const printed = await browser.newPage({ viewport: { width: 1280, height: 720 } });
  await printed.goto(`${base}/${deck}?print-pdf`);
  await printed.waitForFunction(() => window.__shadowlabFitted === true, null, { timeout: 60000 });
  const print = await printed.evaluate(() => ({ frames: document.querySelectorAll('iframe').length,
    stills: [...document.querySelectorAll('.live img')].filter((i) => i.complete && i.naturalWidth > 0).length,
    live: document.querySelectorAll('.live').length }));
  await printed.close();
  if (print.frames || print.stills !== print.live) fail(`${name} printed: ${print.stills} of ${print.live} stills shown, ${print.frames} page(s)`);
  for (const e of errors) fail(`${name}: ${e}`);
}

await browser.close();
server.close();
console.log(failures.length ? `check_slides.mjs: ${failures.length} failure(s)` : `check_slides.mjs: ${decks.length} decks, all held`);
process.exit(failures.length ? 1 : 0);
