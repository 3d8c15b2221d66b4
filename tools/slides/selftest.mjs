#!/usr/bin/env node
// Proof that the slide checks can fail: builds scratch decks that are broken on purpose and asserts
// that the builder or tools/web/check-page.mjs rejects each one for the right reason, plus one clean
// deck that must pass (so a checker that rejects everything does not pass either). Also scans the
// built output for references to the network (decks must open offline).
//   node tools/slides/selftest.mjs --bin DIR [--lesson 01_lighting] [--work DIR]
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const HERE = path.dirname(fileURLToPath(import.meta.url));
const ROOT = path.resolve(HERE, '../..');
const BUILD = path.join(HERE, 'build.mjs');
const CHECK = path.join(ROOT, 'tools/web/check-page.mjs');

const args = process.argv.slice(2);
const opt = (name, def) => { const i = args.indexOf(name); return i >= 0 ? args[i + 1] : def; };
const bin = path.resolve(opt('--bin', path.join(ROOT, 'build/default/bin')));
const lesson = opt('--lesson', '01_lighting');
const work = path.resolve(opt('--work', fs.mkdtempSync(path.join(os.tmpdir(), 'slides-selftest-'))));

const binary = path.join(bin, `lesson_${lesson}`);
const list = spawnSync(binary, ['--list-presets'], { encoding: 'utf8' });
if (list.status !== 0) {
  console.error(`selftest: ${binary} --list-presets failed: ${list.error?.message ?? list.stderr}`);
  process.exit(1);
}
const preset = list.stdout.split('\n').map((s) => s.trim()).filter(Boolean)[0];

let failures = 0;
function node(script, argv) {
  const r = spawnSync(process.execPath, [script, ...argv], { encoding: 'utf8' });
  return { code: r.status, output: `${r.stdout}${r.stderr}` };
}
function expect(name, ok, detail) {
  console.log(`selftest: ${ok ? 'ok  ' : 'FAIL'} ${name}`);
  if (!ok) { failures++; console.log(`  ${detail.trim().replace(/\n/g, '\n  ')}`); }
}

// Each scratch deck lives in its own folder and output, named after the lesson (the builder checks
// that the file name matches the lesson).
function deck(name, body) {
  const dir = path.join(work, name);
  fs.rmSync(dir, { recursive: true, force: true });
  fs.mkdirSync(dir, { recursive: true });
  const file = path.join(dir, `${lesson}.md`);
  fs.writeFileSync(file, `---\nlesson: ${lesson}\ntitle: selftest ${name}\n---\n${body}`);
  const out = path.join(dir, 'out');
  const build = node(BUILD, ['--bin', bin, '--decks', dir, '--out', out, '--no-pdf', '--jobs', '2']);
  return { build, html: path.join(out, `${lesson}.html`), out };
}
const figure = `![a figure](lesson:${lesson}?preset=${preset}&size=160x90&frames=1)`;
const good = `# Clean\n\n$I = k_a I_a + \\sum_i V_i$\n\n---\n## Figure\n\n${figure}\n`;

// 1. The positive control: a clean deck builds and passes.
const clean = deck('clean', good);
expect('clean deck builds', clean.build.code === 0, clean.build.output);
const cleanCheck = node(CHECK, [clean.html, '--expect-slides', '2']);
expect('clean deck passes check-page', cleanCheck.code === 0 && /check-page: ok .*\(2 slides, 1 images, 1 formulas\)/.test(cleanCheck.output), cleanCheck.output);

// 2. Wrong slide count.
const count = node(CHECK, [clean.html, '--expect-slides', '3']);
expect('check-page fails on a wrong slide count', count.code === 1 && /2 slides, expected 3/.test(count.output), count.output);

// 3. A figure that does not load.
const missing = deck('missing_image', good);
for (const f of fs.readdirSync(path.join(missing.out, 'figures'))) fs.rmSync(path.join(missing.out, 'figures', f));
const missingCheck = node(CHECK, [missing.html, '--expect-slides', '2']);
expect('check-page fails on an image that does not load', missingCheck.code === 1 && /image did not load/.test(missingCheck.output), missingCheck.output);

// 4. A formula KaTeX cannot parse: the builder fails, still writes the deck, and the check fails.
const math = deck('bad_formula', `# Bad\n\n$\\frac{1}{$ and $$\\left( x$$\n`);
expect('builder fails on a broken formula', math.build.code === 1 && /KaTeX cannot parse/.test(math.build.output), math.build.output);
const mathCheck = node(CHECK, [math.html, '--expect-slides', '1']);
expect('check-page fails on a .katex-error node', mathCheck.code === 1 && /KaTeX error/.test(mathCheck.output), mathCheck.output);

// 5. A preset the lesson does not have: the build fails with the lesson's list, and writes nothing.
const preset404 = deck('bad_preset', `# Bad\n\n![x](lesson:${lesson}?preset=no_such_preset_xyz)\n`);
expect('builder fails on an unknown preset', preset404.build.code === 1 && /no preset "no_such_preset_xyz"/.test(preset404.build.output) && !fs.existsSync(preset404.html), preset404.build.output);

// 6. A lesson rejecting its parameters (exit 2 with its own message): the build shows that message.
const badSet = deck('bad_set', `# Bad\n\n![x](lesson:${lesson}?preset=${preset}&set=no_such_parameter_xyz=1&size=160x90)\n`);
expect('builder fails when the lesson rejects a --set', badSet.build.code === 1 && /failed \(exit 2\)/.test(badSet.build.output), badSet.build.output);

// 6b. A zoom outside the figure: the build names the option and its valid range. A zoomed figure
// builds and is drawn as the enlarged region (a clipping box holding the whole image).
const badZoom = deck('bad_zoom', `# Bad\n\n![x](lesson:${lesson}?preset=${preset}&size=160x90&zoom=0.9,0,0.2)\n`);
expect('builder fails on a zoom outside the figure', badZoom.build.code === 1 && /zoom=0\.9,0,0\.2 is not X,Y,W/.test(badZoom.build.output), badZoom.build.output);
const zoomed = deck('zoom', `# Zoom\n\n![x](lesson:${lesson}?preset=${preset}&size=160x90&frames=1&zoom=0.5,0.25,0.5)\n`);
const zoomHtml = zoomed.build.code === 0 ? fs.readFileSync(zoomed.html, 'utf8') : '';
expect('a zoomed figure builds into a clipping box', /<span class="zoom" style="width:160px;aspect-ratio:160\/90;--zx:0.5;--zy:0.25;--zw:0.5"[^>]*><img /.test(zoomHtml), zoomed.build.output + zoomHtml.slice(0, 2000));

// 7. A console error and a page error.
const script = deck('console_error', `# Bad\n\n<script>console.error('selftest boom')</script>\n`);
const scriptCheck = node(CHECK, [script.html, '--expect-slides', '1']);
expect('check-page fails on a console error', scriptCheck.code === 1 && /console error: selftest boom/.test(scriptCheck.output), scriptCheck.output);
const thrown = deck('page_error', `# Bad\n\n<script>null.selftest()</script>\n`);
const thrownCheck = node(CHECK, [thrown.html, '--expect-slides', '1']);
expect('check-page fails on an uncaught page error', thrownCheck.code === 1 && /page error/.test(thrownCheck.output), thrownCheck.output);

// 8. A reference to the network (a CDN): blocked and reported.
const cdn = deck('external', `# Bad\n\n<link rel="stylesheet" href="https://cdn.example.invalid/katex.css">\n`);
const cdnCheck = node(CHECK, [cdn.html, '--expect-slides', '1']);
expect('check-page fails on a request leaving the page', cdnCheck.code === 1 && /external request/.test(cdnCheck.output), cdnCheck.output);

// 9. A slide whose content does not fit: cut off in the room and in the PDF.
const tall = deck('overflow', `# Too long\n\n${Array.from({ length: 30 }, (_, i) => `- line ${i + 1}`).join('\n')}\n`);
const tallCheck = node(CHECK, [tall.html, '--expect-slides', '1']);
expect('check-page fails on a slide that overflows', tallCheck.code === 1 && /slide 1 overflows/.test(tallCheck.output), tallCheck.output);

// 9b. Figures left at their size=WxH with room below them (the deck's fit switched off): reported.
const small = deck('small_figure', good);
if (fs.existsSync(small.html)) {
  fs.writeFileSync(small.html, fs.readFileSync(small.html, 'utf8')
    .replace('fitFigures(Reveal.getCurrentSlide())', 'Promise.resolve()').replace('fitFigures(e.currentSlide)', 'Promise.resolve()'));
}
const smallCheck = node(CHECK, [small.html, '--expect-slides', '2']);
expect('check-page fails on figures smaller than their slide allows',
  smallCheck.code === 1 && /slide 2: its figures could be larger/.test(smallCheck.output), smallCheck.output);

// 10. Generated blocks: {{passes}} and {{exercises}} come from the lesson (its main.cpp banners and
// `--info`); an unknown block is an error naming it and the valid ones.
const generated = deck('generated', `# Generated\n\n{{passes}}\n\n---\n## Exercises\n\n{{exercises}}\n`);
const genHtml = fs.existsSync(generated.html) ? fs.readFileSync(generated.html, 'utf8') : '';
const info = JSON.parse(spawnSync(binary, ['--info'], { encoding: 'utf8' }).stdout);
expect('{{passes}} and {{exercises}} become the lesson\'s passes and exercises',
  generated.build.code === 0 && /<ol>\s*<li>/.test(genHtml) && info.exercises.length > 0 &&
  info.exercises.every((e) => genHtml.includes(`<code>${e.function}</code>`) && genHtml.includes(e.file)) &&
  genHtml.includes(info.grade), generated.build.output);
const unknown = deck('bad_generated', `# Bad\n\n{{presets}}\n`);
expect('an unknown {{block}} fails the build, naming the valid ones',
  unknown.build.code === 1 && /:7: unknown generated block \{\{presets\}\}; valid: \{\{passes\}\}, \{\{exercises\}\}/.test(unknown.build.output),
  unknown.build.output);

// 11. The same figure twice in one deck (here, whole and zoomed) renders once, not twice into the
// same temporary file (one run then found its PNG gone).
const zoomOfIt = figure.replace(')', '&zoom=0.25,0.25,0.5)');
const twice = deck('same_figure_twice', `# Twice\n\n${figure}\n\n---\n## Again\n\n${figure}\n\n---\n## Zoomed\n\n${zoomOfIt}\n`);
expect('the same figure twice builds, rendered once', twice.build.code === 0 && /1 figure\(s\) rendered/.test(twice.build.output),
  twice.build.output);

// 12. The builder's own output (HTML, CSS, vendor files) refers to nothing on the network.
const offenders = [];
(function scan(dir) {
  for (const e of fs.readdirSync(dir, { withFileTypes: true })) {
    const p = path.join(dir, e.name);
    if (e.isDirectory()) scan(p);
    else if (/\.(html|css|js)$/.test(e.name)) {
      const text = fs.readFileSync(p, 'utf8');
      const m = text.match(/(?:\b(?:src|href)\s*=\s*["']?|url\(\s*["']?|@import\s+["'])(?:https?:)?\/\/[^"')\s]+/g);
      if (m) offenders.push(`${path.relative(clean.out, p)}: ${m.slice(0, 3).join(', ')}`);
    }
  }
})(clean.out);
expect('built output loads nothing from the network', offenders.length === 0, offenders.join('\n'));

console.log(failures ? `selftest: ${failures} check(s) failed (work dir ${work})` : 'selftest: all checks behave');
process.exit(failures ? 1 : 0);
