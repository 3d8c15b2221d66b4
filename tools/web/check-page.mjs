#!/usr/bin/env node
// Opens an HTML page in headless Chromium and fails when a reader would see something broken:
//   - any console error or uncaught page error,
//   - any request leaving the page's own origin (pages must work offline: no CDN at view time),
//   - any <img> that did not load (naturalWidth 0),
//   - any KaTeX error node (.katex-error: a formula that did not parse),
//   - in a reveal.js deck: a slide whose content overflows the slide (cut off in the room and in the
//     PDF), a formula or code block wider than its slide, figures left smaller than their slide
//     allows (room below them and a figure narrower than its column),
//   - with --expect-slides N: a reveal.js deck whose slide count is not N.
// Usage: node tools/web/check-page.mjs PAGE.html|URL [--expect-slides N] [--timeout-ms MS]
// Exit 0 and one "ok" line when clean; exit 1 with one line per problem, each naming the page.
// Chromium: $SHADOWLAB_CHROMIUM or /usr/bin/chromium (Debian's package; playwright-core drives it).
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { chromium } from 'playwright-core';

export const CHROMIUM = process.env.SHADOWLAB_CHROMIUM || '/usr/bin/chromium';
// --no-sandbox: CI and containers run as root; the rest keep Chromium from phoning home, which on an
// offline machine only produces refused connections and noise.
export const CHROMIUM_ARGS = [
  '--no-sandbox', '--disable-gpu', '--disable-background-networking', '--disable-component-update',
  '--disable-sync', '--no-first-run', '--disable-default-apps', '--disable-extensions',
];

export async function launchChromium() {
  if (!fs.existsSync(CHROMIUM)) {
    throw new Error(`Chromium not found at ${CHROMIUM}: install it (tools/install-deps.sh --slides) or set SHADOWLAB_CHROMIUM`);
  }
  return chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS, headless: true });
}

export function pageUrl(target) {
  if (/^(https?|file):\/\//.test(target)) return target;
  const file = path.resolve(target);
  if (!fs.existsSync(file)) throw new Error(`${target}: no such file`);
  return pathToFileURL(file).href;
}

function sameOrigin(url, base) {
  if (/^(data|blob|about):/.test(url)) return true;
  const u = new URL(url), b = new URL(base);
  if (b.protocol === 'file:') return u.protocol === 'file:';
  return u.origin === b.origin;
}

// Waits for reveal.js (when the page has it), web fonts and every image to settle.
async function settle(page, timeoutMs) {
  await page.waitForLoadState('load', { timeout: timeoutMs });
  await page.evaluate(async (ms) => {
    const deadline = Date.now() + ms;
    const sleep = (t) => new Promise((r) => setTimeout(r, t));
    if (window.Reveal) {
      while (!(window.Reveal.isReady && window.Reveal.isReady()) && Date.now() < deadline) await sleep(25);
    }
    await document.fonts.ready;
    await Promise.all([...document.images].map((img) => (img.complete ? null
      : new Promise((r) => { img.addEventListener('load', r, { once: true }); img.addEventListener('error', r, { once: true }); }))));
  }, timeoutMs);
}

// Returns a list of problems (empty = clean) and a summary of what was looked at.
export async function checkPage(browser, target, { expectSlides = null, timeoutMs = 30_000 } = {}) {
  const url = pageUrl(target);
  const name = target;
  const problems = [];
  const context = await browser.newContext({ viewport: { width: 1280, height: 720 } });
  const page = await context.newPage();
  page.on('console', (msg) => {
    if (msg.type() === 'error') problems.push(`console error: ${msg.text()}${msg.location()?.url ? ` (${msg.location().url})` : ''}`);
  });
  page.on('pageerror', (err) => problems.push(`page error: ${err.message}`));
  page.on('requestfailed', (req) => {
    if (sameOrigin(req.url(), url)) problems.push(`failed to load ${req.url()}: ${req.failure()?.errorText ?? 'unknown error'}`);
  });
  await page.route('**/*', (route) => {
    const u = route.request().url();
    if (sameOrigin(u, url)) return route.continue();
    problems.push(`external request (the page must work offline): ${u}`);
    return route.abort('blockedbyclient');
  });

  let summary = {};
  try {
    const response = await page.goto(url, { waitUntil: 'load', timeout: timeoutMs });
    if (response && !response.ok()) problems.push(`HTTP ${response.status()} for the page itself`);
    await settle(page, timeoutMs);
    summary = await page.evaluate(() => {
      const slideOf = (el) => {
        const s = el.closest('.reveal .slides section');
        if (!s || !window.Reveal) return '';
        const all = [...document.querySelectorAll('.reveal .slides section')].filter((x) => !x.querySelector('section'));
        return ` on slide ${all.indexOf(s.closest('section')) + 1}`;
      };
      const images = [...document.images];
      const broken = images.filter((img) => !img.complete || img.naturalWidth === 0)
        .map((img) => `image did not load: ${img.getAttribute('src')}${slideOf(img)}`);
      const katexErrors = [...document.querySelectorAll('.katex-error')]
        .map((el) => `KaTeX error${slideOf(el)}: ${el.getAttribute('title') || el.textContent}`);
      return {
        images: images.length,
        formulas: document.querySelectorAll('.katex').length,
        problems: [...broken, ...katexErrors],
        reveal: !!window.Reveal,
        slides: window.Reveal && window.Reveal.getTotalSlides ? window.Reveal.getTotalSlides() : null,
      };
    });
    problems.push(...summary.problems);
    // A reveal.js slide is a fixed-size page: content below or beside it is cut off in the room and
    // in the PDF. Visit every slide and measure it (hidden slides have no layout).
    if (summary.reveal) {
      problems.push(...await page.evaluate(async () => {
        const R = window.Reveal, { width, height } = R.getConfig();
        const out = [];
        const slides = R.getSlides();
        for (let n = 0; n < slides.length; n++) {
          const s = slides[n];
          const { h, v } = R.getIndices(s);
          R.slide(h, v);
          await new Promise((r) => requestAnimationFrame(() => r()));
          // A deck's figures fill their slide (tools/slides/build.mjs, fitFigures): wait for the
          // fit, then a slide with room below and a figure narrower than its column is a problem.
          const figs = [...s.querySelectorAll('.figrow figure')];
          for (let t = 0; figs.length && !s.dataset.fitted && t < 80; t++) await new Promise((r) => setTimeout(r, 25));
          if (figs.length) {
            const bottom = Math.max(...[...s.children].filter((c) => !c.matches('aside')).map((c) => c.offsetTop + c.offsetHeight));
            const narrow = figs.filter((f) => {  // the column: the row's width shared by its figures (18px gaps)
              const row = f.parentElement, count = row.querySelectorAll(':scope > figure').length;
              return (f.querySelector('.zoom') || f.querySelector('img')).offsetWidth < (row.clientWidth - 18 * (count - 1)) / count - 4;
            });
            if (height - bottom > 40 && narrow.length) {
              out.push(`slide ${n + 1}: its figures could be larger (${height - bottom}px free below, ${narrow.length} figure(s) narrower than their column)`);
            }
          }
          const tall = s.scrollHeight - height, wide = s.scrollWidth - width;
          if (tall > 2) out.push(`slide ${n + 1} overflows the ${height}px slide height by ${tall}px (content is cut off)`);
          if (wide > 2) out.push(`slide ${n + 1} overflows the ${width}px slide width by ${wide}px`);
          for (const el of s.querySelectorAll('.math-display, pre')) {
            if (el.scrollWidth > el.clientWidth + 2) {
              out.push(`slide ${n + 1}: ${el.matches('pre') ? 'code block' : 'formula'} wider than the slide by ${el.scrollWidth - el.clientWidth}px: ${el.textContent.trim().slice(0, 60)}`);
            }
          }
        }
        R.slide(0, 0);
        return out;
      }));
    }
    if (expectSlides !== null) {
      if (!summary.reveal) problems.push(`--expect-slides ${expectSlides} but the page is not a reveal.js deck`);
      else if (summary.slides !== expectSlides) problems.push(`${summary.slides} slides, expected ${expectSlides} (from the source)`);
    }
  } catch (e) {
    problems.push(`could not check the page: ${e.message.split('\n')[0]}`);
  } finally {
    await context.close();
  }
  return { name, problems, summary };
}

function usage(message) {
  console.error(`check-page: ${message}\nusage: node tools/web/check-page.mjs PAGE.html|URL [--expect-slides N] [--timeout-ms MS]`);
  process.exit(2);
}

async function main(argv) {
  const targets = [];
  let expectSlides = null, timeoutMs = 30_000;
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (a === '--expect-slides') {
      if (!/^\d+$/.test(argv[i + 1] ?? '')) usage('--expect-slides needs a count');
      expectSlides = Number(argv[++i]);
    } else if (a === '--timeout-ms') {
      if (!/^\d+$/.test(argv[i + 1] ?? '')) usage('--timeout-ms needs milliseconds');
      timeoutMs = Number(argv[++i]);
    } else if (a === '-h' || a === '--help') usage('help');
    else if (a.startsWith('--')) usage(`unknown option ${a}`);
    else targets.push(a);
  }
  if (targets.length !== 1) usage('give exactly one page');
  let browser;
  try {
    browser = await launchChromium();
    const { name, problems, summary } = await checkPage(browser, targets[0], { expectSlides, timeoutMs });
    if (problems.length) {
      for (const p of problems) console.error(`check-page: FAIL ${name}: ${p}`);
      return 1;
    }
    const slides = summary.slides !== null && summary.slides !== undefined ? `${summary.slides} slides, ` : '';
    console.log(`check-page: ok ${name} (${slides}${summary.images} images, ${summary.formulas} formulas)`);
    return 0;
  } catch (e) {
    console.error(`check-page: FAIL ${targets[0]}: ${e.message.split('\n')[0]}`);
    return 1;
  } finally {
    await browser?.close();
  }
}

// Run as a script (also through a symlinked path: Node gives import.meta.url the real path).
if (process.argv[1] && fs.realpathSync(process.argv[1]) === fileURLToPath(import.meta.url)) {
  process.exitCode = await main(process.argv.slice(2));
}
