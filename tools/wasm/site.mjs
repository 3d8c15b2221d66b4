// site.mjs: the browser build's index page, BUILD/site/index.html: every lesson page with its
// summary, difficulty, presets (each a link that opens the page at it) and links to its README
// (rendered to readme/NN_name.html) and its slides (slides/NN_name.html, where the site has the
// decks: tools/wasm/build.sh puts them there), generated from the native lessons' registries
// (--info, --list-presets), so it cannot drift.
//   node tools/wasm/site.mjs --build build/web [--bin build/default/bin]
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { Marked } from '../slides/deps.mjs';

const opts = { build: 'build/web', bin: 'build/default/bin' };
for (let i = 2; i < process.argv.length; i += 2) opts[process.argv[i].replace(/^--/, '')] = process.argv[i + 1];
const site = path.join(opts.build, 'site');
const escape = (s) => String(s).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);

const pages = fs.readdirSync(site).filter((f) => /^lesson_\d\d_.*\.html$/.test(f)).sort();
if (pages.length === 0) {
  console.error(`site.mjs: no lesson pages in ${site}`);
  process.exit(1);
}
const rows = pages.map((page) => {
  const name = page.replace(/^lesson_|\.html$/g, '');
  const binary = path.join(opts.bin, `lesson_${name}`);
  let info = { number: name.slice(0, 2), title: name.slice(3).replace(/_/g, ' '), summary: '', difficulty: 0 };
  let presets = [];
  if (fs.existsSync(binary)) {
    info = JSON.parse(spawnSync(binary, ['--info'], { encoding: 'utf8' }).stdout);
    presets = spawnSync(binary, ['--list-presets'], { encoding: 'utf8' }).stdout.split('\n').filter(Boolean);
  }
  const readme = path.join('lessons', name, 'README.md');  // beside the page: the site stands alone
  fs.mkdirSync(path.join(site, 'readme'), { recursive: true });
  if (fs.existsSync(readme)) fs.writeFileSync(path.join(site, 'readme', `${name}.html`), readmePage(info, page, readme));
  const slides = fs.existsSync(path.join(site, 'slides', `${name}.html`)) ? `<a href="slides/${name}.html">slides</a>` : '';
  const links = presets.filter((p) => p !== 'default')
                       .map((p) => `<a href="${page}?preset=${encodeURIComponent(p)}">${escape(p)}</a>`).join(' ');
  return `<tr><td class="n">${escape(info.number)}</td><td><a class="title" href="${page}">${escape(info.title)}</a>` +
         `<div class="summary">${escape(info.summary)}</div><div class="presets">${links}</div></td>` +
         `<td class="d">${'&#9679;'.repeat(info.difficulty)}</td>` +
         `<td class="links"><a href="readme/${name}.html">README</a> ${slides}</td></tr>`;
});
// A lesson's README as a page of the site, with a way back and the lesson's page at the top.
function readmePage(info, page, file) {
  const body = new Marked({ gfm: true }).parse(fs.readFileSync(file, 'utf8'));
  return `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><meta name="viewport" content="width=device-width, initial-scale=1">
<title>${escape(info.number)} ${escape(info.title)}: README</title>
<style>
body { font: 18px/1.5 system-ui, sans-serif; background: #15171c; color: #e8e8e8; max-width: 960px; margin: 2em auto; padding: 0 1em; }
a { color: #8cf; } code, pre { background: #22252c; } pre { padding: 0.6em; overflow-x: auto; }
table { border-collapse: collapse; } td, th { border: 1px solid #333; padding: 0.3em 0.6em; }
</style></head><body>
<p><a href="../index.html">all lessons</a> &middot; <a href="../${page}">run the lesson</a></p>
${body}
</body></html>
`;
}

const html = `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><meta name="viewport" content="width=device-width, initial-scale=1">
<title>shadowlab: the lessons in the browser</title>
<style>
body { font: 18px/1.45 system-ui, sans-serif; background: #15171c; color: #e8e8e8; max-width: 1100px; margin: 2em auto; padding: 0 1em; }
a { color: #8cf; } table { border-collapse: collapse; width: 100%; } td { padding: 0.6em; vertical-align: top; border-top: 1px solid #333; }
.n { font-size: 1.6em; color: #889; } .title { font-size: 1.25em; } .summary { color: #bbc; } .presets a { margin-right: 0.6em; font-size: 0.85em; }
.d { color: #fc6; white-space: nowrap; } .links a { margin-right: 0.6em; white-space: nowrap; }
</style></head><body>
<h1>shadowlab: real-time shadows and texture filtering, in the browser</h1>
<p>Each lesson is the course's own program compiled to WebAssembly and WebGL2. Drag to orbit, F1 for help, F3 for
the parameters; a preset link opens the lesson at it. The ground truth (the error overlays), model files and the
lessons not listed here run natively: <code>make run</code>.${fs.existsSync(path.join(site, 'slides', 'index.html')) ? ' Every lesson\'s slides: <a href="slides/index.html">the decks</a>.' : ''}</p>
<table>${rows.join('\n')}</table>
</body></html>
`;
fs.writeFileSync(path.join(site, 'index.html'), html);
console.log(`site.mjs: ${site}/index.html (${pages.length} lessons)`);
