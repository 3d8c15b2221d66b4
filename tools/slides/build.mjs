#!/usr/bin/env node
// Builds the lesson decks slides/NN_name.md into static reveal.js HTML (+ a PDF of each) with
// KaTeX formulas rendered at build time and figures rendered by the lessons themselves.
//
//   node tools/slides/build.mjs [--bin build/default/bin] [--out out/slides] [--decks slides]
//                               [--no-pdf] [--jobs N] [DECK.md ...]
//
// Output: OUT/NN_name.html, OUT/NN_name.pdf, OUT/index.html, OUT/figures/*.png and OUT/vendor/
// (reveal.js, KaTeX CSS and fonts): everything local, so a deck opens from file:// with no network.
// Deck syntax: slides/README.md. Exit 1 with file:line and the reason on any error (a figure the
// lesson cannot render, a formula KaTeX cannot parse, a missing image).
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { DeckError, escapeHtml, expandGenerated, makeMarkdown, parseDeck, passesOf, usesGenerated } from './deck.mjs';
import { webPackageDir } from './deps.mjs';
import { FigureError, FigureRenderer, livePage, parseFigureUrl } from './figures.mjs';

const HERE = path.dirname(fileURLToPath(import.meta.url));
const ROOT = path.resolve(HERE, '../..');

function parseArgs(argv) {
  const opts = {
    bin: path.join(ROOT, 'build/default/bin'),
    out: path.join(ROOT, 'out/slides'),
    decks: path.join(ROOT, 'slides'),
    pdf: true,
    jobs: Math.max(1, os.availableParallelism?.() ?? os.cpus().length),
    only: [],
  };
  const need = (i) => {
    if (argv[i + 1] === undefined) fail(`${argv[i]} needs a value`, 2);
    return argv[i + 1];
  };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (a === '--bin') opts.bin = path.resolve(need(i++));
    else if (a === '--out') opts.out = path.resolve(need(i++));
    else if (a === '--decks') opts.decks = path.resolve(need(i++));
    else if (a === '--no-pdf') opts.pdf = false;
    else if (a === '--jobs') opts.jobs = Math.max(1, Number(need(i++)) || 1);
    else if (a === '-h' || a === '--help') {
      console.log(fs.readFileSync(fileURLToPath(import.meta.url), 'utf8').split('\n').slice(1, 11).join('\n').replace(/^\/\/ ?/gm, ''));
      process.exit(0);
    } else if (a.startsWith('--')) fail(`unknown option ${a} (see --help)`, 2);
    else opts.only.push(path.resolve(a));
  }
  return opts;
}

function fail(message, code = 1) {
  console.error(`slides: ${message}`);
  process.exit(code);
}

// Decks are slides/NN_name.md; README.md and anything else is not a deck.
function findDecks(opts) {
  if (opts.only.length) return opts.only;
  if (!fs.existsSync(opts.decks)) fail(`no deck folder ${opts.decks}`);
  return fs.readdirSync(opts.decks).filter((f) => /^\d\d_[a-z0-9_]+\.md$/.test(f)).sort()
    .map((f) => path.join(opts.decks, f));
}

function copyFile(from, to) {
  fs.mkdirSync(path.dirname(to), { recursive: true });
  const a = fs.statSync(from);
  try {
    const b = fs.statSync(to);
    if (b.size === a.size && b.mtimeMs >= a.mtimeMs) return;
  } catch { /* not there yet */ }
  fs.copyFileSync(from, to);
}

function copyDir(from, to) {
  for (const e of fs.readdirSync(from, { withFileTypes: true })) {
    if (e.isDirectory()) copyDir(path.join(from, e.name), path.join(to, e.name));
    else copyFile(path.join(from, e.name), path.join(to, e.name));
  }
}

// reveal.js and KaTeX's stylesheet and fonts, copied next to the decks (no CDN at view time).
function copyVendor(out) {
  const reveal = webPackageDir('reveal.js');
  const katex = webPackageDir('katex');
  const v = path.join(out, 'vendor');
  for (const f of ['reset.css', 'reveal.css', 'reveal.js', 'theme/white.css']) copyFile(path.join(reveal, 'dist', f), path.join(v, 'reveal', f));
  copyDir(path.join(reveal, 'dist/theme/fonts/source-sans-pro'), path.join(v, 'reveal/theme/fonts/source-sans-pro'));
  copyFile(path.join(reveal, 'plugin/notes/notes.js'), path.join(v, 'reveal/plugin/notes/notes.js'));
  copyFile(path.join(katex, 'dist/katex.min.css'), path.join(v, 'katex/katex.min.css'));
  copyDir(path.join(katex, 'dist/fonts'), path.join(v, 'katex/fonts'));
  copyFile(path.join(HERE, 'theme.css'), path.join(out, 'shadowlab.css'));
}

const HEAD = (title) => `<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>${escapeHtml(title)}</title>
<link rel="icon" href="data:,">
<link rel="stylesheet" href="vendor/reveal/reset.css">
<link rel="stylesheet" href="vendor/reveal/reveal.css">
<link rel="stylesheet" href="vendor/reveal/theme/white.css">
<link rel="stylesheet" href="vendor/katex/katex.min.css">
<link rel="stylesheet" href="shadowlab.css">
</head>`;

// Figures as large as their slide allows, for the back of the room: once a slide is laid out (its
// images and fonts loaded), every figure of it is scaled by one common factor, found by bisection,
// until the slide's content reaches its bottom (8 px spare) or each figure its column's width (a
// figure too large for its slide shrinks the same way). size=WxH sets the figures' proportions
// and their size where scripts do not run. Runs for the slide shown, and for every slide when
// printing (?print-pdf: after reveal.js lays out the pages; window.__shadowlabFitted says when it is
// done, and the PDF waits for it). The deck checker's overflow test visits each slide after it ran.
const FIT_FIGURES = `function fitFigures(s) {
  const figs = s ? [...s.querySelectorAll('.figrow figure')].map((f) => f.querySelector('.zoom') || f.querySelector('img')) : [];
  if (!figs.length || s.dataset.fitted) return Promise.resolve();
  const imgs = [...s.querySelectorAll('.figrow img')];
  return Promise.all([document.fonts.ready, ...imgs.map((i) => (i.complete ? null
    : new Promise((r) => { i.addEventListener('load', r, { once: true }); i.addEventListener('error', r, { once: true }); })))])
    .then(() => {
      if (s.dataset.fitted || !s.offsetHeight) return;
      const limit = Reveal.getConfig().height - 8;
      const bottom = () => Math.max(...[...s.children].filter((c) => !c.matches('aside'))
        .map((c) => c.offsetTop + c.offsetHeight));
      const base = figs.map((e) => e.offsetWidth);
      const set = (k) => figs.forEach((e, i) => { e.style.width = (base[i] * k).toFixed(1) + 'px'; });
      let lo = 0.25, hi = 12;
      for (let it = 0; it < 14; ++it) { const k = (lo + hi) / 2; set(k); if (bottom() <= limit) lo = k; else hi = k; }
      set(lo);
      s.dataset.fitted = '1';
    });
}
// Live figures (live=...): the slide shown gets the lesson's page over each still (an iframe the
// still's size, scaled with it), once its figures are fitted; the slide left loses them, so only
// the slide on screen runs a lesson (a deck of fifteen live slides never runs fifteen at once).
// The stills stay where the page cannot run: a PDF, a deck opened from disk (no server for the
// WebAssembly), a browser without WebGL2, a deck without the site's pages (make slides), ?live=off.
// The deck's own ?set=name=value reach every live page (a slow laptop: ?set=budget.fps=10).
const live = {
  on: !/print-pdf|[?&]live=off/.test(location.search) && /^https?:$/.test(location.protocol) &&
      !!document.createElement('canvas').getContext('webgl2'),
  sets: new URLSearchParams(location.search).getAll('set'),
  start(slide) {
    if (!live.on || !slide) return;
    for (const box of slide.querySelectorAll('.live')) {
      fetch(box.dataset.page, { method: 'HEAD' }).then((r) => {
        if (!r.ok || Reveal.getCurrentSlide() !== slide || box.querySelector('iframe')) return;
        const [w, h] = box.dataset.size.split('x').map(Number), img = box.querySelector('img');
        const f = document.createElement('iframe');
        f.src = box.dataset.page + live.sets.map((s) => '&set=' + encodeURIComponent(s)).join('');
        f.width = w;
        f.height = h;
        f.title = 'the lesson, live';
        f.style.transform = 'scale(' + img.clientWidth / w + ')';
        box.appendChild(f);
      }).catch(() => {});
    }
  },
  stop(slide) { if (slide) slide.querySelectorAll('.live iframe').forEach((f) => f.remove()); },
};
if (/print-pdf/.test(window.location.search)) {
  document.addEventListener('pdf-ready', () => Promise.all(Reveal.getSlides().map(fitFigures))
    .then(() => { window.__shadowlabFitted = true; }));
} else {
  Reveal.on('ready', () => fitFigures(Reveal.getCurrentSlide()).then(() => live.start(Reveal.getCurrentSlide())));
  Reveal.on('slidechanged', (e) => {
    live.stop(e.previousSlide);
    fitFigures(e.currentSlide).then(() => live.start(e.currentSlide));
  });
}`;

function deckHtml(deck, sections) {
  return `${HEAD(`${deck.meta.title} - shadowlab`)}
<body>
<div class="reveal"><div class="slides">
${sections.join('\n')}
</div></div>
<script src="vendor/reveal/reveal.js"></script>
<script src="vendor/reveal/plugin/notes/notes.js"></script>
<script>
Reveal.initialize({
  hash: true, width: 1280, height: 720, margin: 0.04, center: false,
  slideNumber: 'c/t', transition: 'none', pdfMaxPagesPerSlide: 1, pdfSeparateFragments: false,
  plugins: [RevealNotes]
});
${FIT_FIGURES}
</script>
</body>
</html>
`;
}

// Local images other than lesson figures are copied to OUT/media/<deck>/...
function resolveLocalImage(href, deckFile, out, deckName) {
  if (/^[a-z][a-z0-9+.-]*:/i.test(href) || href.startsWith('//')) {
    throw new Error(`image "${href}" is not local: decks must work offline (put the file next to the deck)`);
  }
  const src = path.resolve(path.dirname(deckFile), decodeURI(href));
  if (!fs.existsSync(src)) throw new Error(`image "${href}" not found (${src})`);
  const rel = `media/${deckName}/${path.relative(path.dirname(deckFile), src).replace(/\.\.\//g, '_up_/')}`;
  copyFile(src, path.join(out, rel));
  return rel;
}

async function buildDeck(file, opts, figures, usedFigures) {
  const rel = path.relative(process.cwd(), file);
  const deckName = path.basename(file, '.md');
  const deck = parseDeck(fs.readFileSync(file, 'utf8'), rel);
  if (deckName !== deck.meta.lesson && !opts.only.length) {
    throw new DeckError(rel, 1, `deck file name ${deckName}.md does not match its lesson "${deck.meta.lesson}"`);
  }
  if (usesGenerated(deck.slides)) {
    const mainCpp = path.join(ROOT, 'lessons', deck.meta.lesson, 'main.cpp');
    const passes = fs.existsSync(mainCpp) ? passesOf(fs.readFileSync(mainCpp, 'utf8')) : [];
    let info = null;
    try { info = (await figures.lesson(deck.meta.lesson)).info; } catch (e) { throw new DeckError(rel, 0, e.message); }
    expandGenerated(deck.slides, { passes, info }, rel);
  }
  const md = makeMarkdown();
  const lexed = deck.slides.map((s) => ({ ...s, ...md.lex(s.markdown) }));

  // Render every figure of the deck (in parallel, up to --jobs), then rewrite the hrefs.
  const jobs = [];
  lexed.forEach((slide, n) => {
    for (const img of slide.images) {
      const where = `${rel}:${slide.line} (slide ${n + 1})`;
      if (img.href.startsWith('lesson:')) {
        let spec;
        try { spec = parseFigureUrl(img.href); } catch (e) { throw new DeckError(where, 0, e.message); }
        if (spec.zoom) img.zoom = { ...spec.zoom, size: spec.size };
        if (spec.live) img.live = { page: livePage(spec), size: spec.size };
        jobs.push(figures.render(spec).then((out) => { img.href = out; usedFigures.add(out); })
          .catch((e) => { throw Object.assign(new Error(e.message), { where }); }));
      } else {
        try { img.href = resolveLocalImage(img.href, file, opts.out, deckName); } catch (e) { throw new Error(`${where}: ${e.message}`); }
      }
    }
  });
  const results = await Promise.allSettled(jobs);
  const failed = results.filter((r) => r.status === 'rejected');
  if (failed.length) {
    // One line per distinct failure (a missing binary fails every figure the same way).
    const byMessage = new Map();
    for (const { reason } of failed) {
      if (!byMessage.has(reason.message)) byMessage.set(reason.message, []);
      byMessage.get(reason.message).push(reason.where ?? rel);
    }
    throw new Error([...byMessage].map(([message, wheres]) =>
      `${wheres[0]}${wheres.length > 1 ? ` (and ${wheres.length - 1} more figure(s))` : ''}: ${message}`).join('\n'));
  }

  const mathErrors = [];
  const sections = lexed.map((slide, n) => {
    const ctx = { mathErrors: [] };
    let html = md.render(slide.tokens, ctx);
    if (slide.notes?.trim()) html += `<aside class="notes">${md.render(md.lex(slide.notes).tokens, ctx)}</aside>\n`;
    for (const tex of ctx.mathErrors) mathErrors.push(`${rel}:${slide.line} (slide ${n + 1}): KaTeX cannot parse: ${tex}`);
    const cls = n === 0 ? ' class="title-slide"' : '';
    return `<section id="slide-${n + 1}"${cls} data-source-line="${slide.line}">\n${html}</section>`;
  });
  const htmlFile = path.join(opts.out, `${deckName}.html`);
  fs.writeFileSync(htmlFile, deckHtml(deck, sections));
  let info = null;
  try { info = (await figures.lesson(deck.meta.lesson)).info; } catch { /* a deck without figures may predate its binary */ }
  return { file: rel, name: deckName, meta: deck.meta, slides: sections.length, htmlFile, mathErrors, info };
}

function indexHtml(decks, opts) {
  const rows = decks.map((d) => {
    const number = d.info?.number ?? d.meta.lesson.slice(0, 2);
    const lessonTitle = d.info?.title ?? d.meta.lesson;
    const summary = d.info?.summary ? `<div class="summary">${escapeHtml(d.info.summary)}</div>` : '';
    const pdf = opts.pdf ? ` &middot; <a href="${d.name}.pdf">PDF</a>` : '';
    return `<tr><td class="num">${escapeHtml(number)}</td><td><a href="${d.name}.html"><strong>${escapeHtml(d.meta.title)}</strong></a>${pdf}` +
      `<div>lesson <code>lessons/${escapeHtml(d.meta.lesson)}</code>: ${escapeHtml(lessonTitle)}</div>${summary}</td><td>${d.slides} slides</td></tr>`;
  });
  return `<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>shadowlab slides</title>
<link rel="icon" href="data:,">
<link rel="stylesheet" href="vendor/reveal/theme/fonts/source-sans-pro/source-sans-pro.css">
<link rel="stylesheet" href="shadowlab.css">
</head>
<body class="index">
<h1>shadowlab slides</h1>
<p>One deck per lesson; every figure is rendered by the lesson itself. Press <kbd>S</kbd> in a deck for speaker notes, <kbd>Esc</kbd> for the overview.</p>
<table>
<tr><th>#</th><th>deck and lesson</th><th></th></tr>
${rows.join('\n')}
</table>
</body>
</html>
`;
}

// PDF of each deck through headless Chromium, using reveal.js's print layout (one slide a page).
async function buildPdfs(decks, opts) {
  const { launchChromium } = await import(pathToFileURL(path.join(ROOT, 'tools/web/check-page.mjs')).href);
  const browser = await launchChromium();
  try {
    for (const d of decks) {
      const page = await browser.newPage({ viewport: { width: 1280, height: 720 } });
      const errors = [];
      page.on('pageerror', (e) => errors.push(e.message));
      // Reveal.isReady() turns true before the print layout is built (reveal.js 5 lays the pages
      // out after an animation frame, then dispatches 'pdf-ready'); printing in between gave a
      // one-page PDF on a loaded CI machine. Wait for the event itself.
      await page.addInitScript(() => document.addEventListener('pdf-ready', () => { window.__shadowlabPdfReady = true; }));
      await page.goto(`${pathToFileURL(d.htmlFile).href}?print-pdf`, { waitUntil: 'load' });
      await page.waitForFunction(() => window.__shadowlabPdfReady === true && window.__shadowlabFitted === true, null,
        { timeout: 60_000 });
      await page.evaluate(() => document.fonts.ready);
      if (errors.length) throw new Error(`${d.file}: page error while printing: ${errors[0]}`);
      d.pdfFile = path.join(opts.out, `${d.name}.pdf`);
      await page.pdf({ path: d.pdfFile, preferCSSPageSize: true, printBackground: true });
      await page.close();
      // One page a slide: more means a slide overflowed onto a second page (content too long).
      const pages = (fs.readFileSync(d.pdfFile, 'latin1').match(/\/Type\s*\/Page\b(?!s)/g) ?? []).length;
      if (pages !== d.slides) throw new Error(`${d.file}: the PDF has ${pages} pages for ${d.slides} slides (a slide too long for one page?)`);
    }
  } finally {
    await browser.close();
  }
}

async function main() {
  const t0 = performance.now();
  const opts = parseArgs(process.argv.slice(2));
  const files = findDecks(opts);
  if (!files.length) fail(`no decks (slides/NN_name.md) in ${opts.decks}`);
  fs.mkdirSync(opts.out, { recursive: true });
  copyVendor(opts.out);

  const figures = new FigureRenderer({ binDir: opts.bin, outDir: opts.out, jobs: opts.jobs });
  const used = new Set();
  const decks = [];
  const errors = [];
  for (const f of files) {
    try {
      decks.push(await buildDeck(f, opts, figures, used));
    } catch (e) {
      errors.push(e instanceof DeckError || e instanceof FigureError ? e.message : e.message || String(e));
    }
  }
  // Decks with a broken formula are still written (open one to see the red KaTeX error in place),
  // but the build fails.
  errors.push(...decks.flatMap((d) => d.mathErrors));
  if (errors.length) {
    for (const e of errors) console.error(`slides: ${e}`);
    fail(`${errors.length} error(s); nothing is published with a broken figure or formula`);
  }
  decks.sort((a, b) => a.name.localeCompare(b.name));
  if (!opts.only.length) figures.prune(used);
  const indexFile = path.join(opts.out, 'index.html');
  fs.writeFileSync(indexFile, indexHtml(decks, opts));
  if (opts.pdf) await buildPdfs(decks, opts);

  const secs = ((performance.now() - t0) / 1000).toFixed(1);
  for (const d of decks) console.log(`slides: ${d.file} -> ${path.relative(process.cwd(), d.htmlFile)}${opts.pdf ? ' + .pdf' : ''} (${d.slides} slides)`);
  console.log(`slides: ${decks.length} deck(s), ${figures.stats.rendered} figure(s) rendered, ${figures.stats.cached} cached, ${secs} s`);
  console.log(path.relative(process.cwd(), indexFile) || indexFile);
}

main().catch((e) => fail(e.stack || e.message));
