#!/usr/bin/env node
// The lesson READMEs and the top README's lessons table, kept true to the lessons.
//
//   node tools/docs/lesson_docs.mjs --bin build/default/bin --write   fill the generated blocks
//   node tools/docs/lesson_docs.mjs --bin build/default/bin --check   check them and the structure
//        [--root DIR] [--lesson NN_name --readme FILE]   (one README, e.g. a test fixture)
//        [--lesson NN_name --help-text FILE]              (a help text checked against the lesson's keys)
//
// Generated blocks (between `<!-- NAME: ... -->` and `<!-- /NAME -->`), from the lesson itself:
//   hotkeys  the lesson's own keys (`lesson --list-hotkeys`), in each lesson README's Controls
//   presets  every preset and what it shows (the comment above or under it in presets.txt), in
//            Controls; a preset without one is a finding
//   lessons  the top README's table: number, title, summary, time in class, prerequisites (`--info`)
//   assignments  docs/teaching.md's table: each lesson's exercises (id, function, C++ or GLSL) and
//            the command that grades them (`--info`)
// docs/teaching.md's term plan names presets in table rows whose second cell is a lesson number:
// each `--preset NAME` of such a row must be a preset of a lesson that row names.
// The structure every lesson README keeps (docs/teaching.md says why), checked with --check:
//   the `##` sections in this order: What you will learn (3-5 bullets), Time and prerequisites
//   (`**Time in class:** N minutes` and `**Prerequisites:**` naming exactly the lessons --info
//   names), Theory, The passes (one item per `// ==== N. title` banner of main.cpp, in order),
//   Controls, What to try (each bullet starts with an existing `--preset NAME`), Exercises (every
//   exercise's id and `make grade LESSON=NN`), Measured, and optionally References; every
//   `--preset NAME` anywhere names a preset the lesson has; no ctest grading command (ctest does
//   not rebuild) and no dated diary (a month and a year: the history lives in git).
// Each lesson's F1 help text (`--info`'s help) names a key only where it names what the key drives:
// a key mentioned as "T:", "(T)", "(T: ...)", "(1)", "T cycles/toggles/turns" or "press T" must be bound
// (`--list-hotkeys`) to a parameter named on the same line (the generated key list follows the text
// in the F1 window; a hand-written letter drifts: lesson 05's said A and E, keys the fly camera took).
// Exit 0 when all is well (or written), 1 with one `file:line: problem` per finding, 2 on bad usage.
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const HERE = path.dirname(fileURLToPath(import.meta.url));

export const SECTIONS = ['What you will learn', 'Time and prerequisites', 'Theory', 'The passes', 'Controls',
  'What to try', 'Exercises', 'Measured'];
const OPTIONAL_LAST = 'References';
const MONTHS = 'January|February|March|April|May|June|July|August|September|October|November|December';

function usage(message) {
  console.error(`lesson_docs: ${message}\nusage: lesson_docs.mjs --bin DIR (--write | --check) [--root DIR] [--lesson NN_name --readme FILE]`);
  process.exit(2);
}

function parseArgs(argv) {
  const o = { root: path.resolve(HERE, '../..'), bin: null, mode: null, lesson: null, readme: null, helpText: null };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    const value = () => (argv[i + 1] === undefined ? usage(`${a} needs a value`) : argv[++i]);
    if (a === '--bin') o.bin = path.resolve(value());
    else if (a === '--root') o.root = path.resolve(value());
    else if (a === '--lesson') o.lesson = value();
    else if (a === '--readme') o.readme = path.resolve(value());
    else if (a === '--help-text') o.helpText = path.resolve(value());
    else if (a === '--write' || a === '--check') o.mode = a.slice(2);
    else usage(`unknown argument '${a}'`);
  }
  if (!o.bin || !o.mode) usage('--bin and one of --write, --check are required');
  if (!!o.lesson !== !!(o.readme || o.helpText)) usage('--lesson goes with --readme or --help-text');
  return o;
}

function run(binary, args) {
  const r = spawnSync(binary, args, { encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`${binary} ${args.join(' ')} failed (exit ${r.status}): ${r.error?.message ?? r.stderr}`);
  return r.stdout;
}

// What a lesson says about itself, and what its folder holds.
function lessonFacts(root, bin, name) {
  const binary = path.join(bin, `lesson_${name}`);
  const info = JSON.parse(run(binary, ['--info']).trim().split('\n').pop());
  const presets = run(binary, ['--list-presets']).split('\n').map((s) => s.trim()).filter(Boolean);
  const hotkeys = run(binary, ['--list-hotkeys']).split('\n').filter((l) => l.trim() && !l.includes('(framework)'))
    .map((l) => l.trim().split(/\s{2,}/));
  const framework = run(binary, ['--list-hotkeys']).split('\n').filter((l) => l.includes('(framework)'))
    .map((l) => l.trim().split(/\s+/)[0]);
  const main = fs.readFileSync(path.join(root, 'lessons', name, 'main.cpp'), 'utf8');
  const passes = [...main.matchAll(/^\s*\/\/ ==== (\d+[a-z]?)\. /gm)].map((m) => m[1]);
  const comments = presetComments(fs.readFileSync(path.join(root, 'lessons', name, 'presets.txt'), 'utf8'));
  return { name, info, presets, hotkeys, framework, passes, comments };
}

// presets.txt: each [name] and what it shows: the comment block right above it (a section line
// "# ----" and the file's opening block are not), else the comment lines right under it, joined.
function presetComments(text) {
  const out = new Map();
  const lines = text.split('\n');
  lines.forEach((line, i) => {
    const m = /^\[([^\]]+)\]/.exec(line);
    if (!m) return;
    const above = [];
    let j = i - 1;
    for (; j >= 0 && lines[j].startsWith('#') && !lines[j].startsWith('# ----'); --j) above.unshift(lines[j]);
    const below = [];
    for (let k = i + 1; k < lines.length && lines[k].startsWith('#'); ++k) below.push(lines[k]);
    const chosen = above.length && j >= 0 ? above : below;
    out.set(m[1], chosen.map((l) => l.slice(1).trim()).join(' ').trim());
  });
  return out;
}

const cell = (s) => s.replace(/\|/g, '\\|');

function hotkeysBlock(f) {
  const rows = f.hotkeys.map(([key, param, action]) => `| \`${key}\` | \`${param}\` | ${cell(action ?? '')} |`);
  const key = (f.info.key_figures ?? []).map((k) => `\`${k}\``).join(', ');
  return ['| key | parameter | does |', '|---|---|---|', ...rows, '',
    `The header shows the lesson's key figures${key ? ` (${key}, where the technique has them)` : ''} and, with M, ` +
    "the ground truth's; every other figure this page reads \"in the header\" is in the stats (F2)."].join('\n');
}

function presetsBlock(f) {
  const rows = f.presets.map((p) => `| \`${p}\` | ${cell(f.comments.get(p) || (p === 'default' ? "the lesson's defaults" : ''))} |`);
  return ['| preset | shows |', '|---|---|', ...rows].join('\n');
}

function lessonsBlock(all) {
  const rows = all.map(({ name, info }) => {
    const after = info.prerequisites.length ? info.prerequisites.join(', ') : '-';
    return `| ${info.number} | [${cell(info.title)}](lessons/${name}/README.md) | ${cell(info.summary)} | ${info.minutes} min | ${after} |`;
  });
  return ['| # | lesson | what it teaches | time in class | after |', '|---|---|---|---|---|', ...rows].join('\n');
}

function assignmentsBlock(all) {
  const rows = all.map(({ info }) => {
    const list = info.exercises.map((e) => `${e.id} \`${e.function}\`${e.glsl ? ' (GLSL)' : ''}`).join(', ');
    return `| ${info.number} | ${cell(info.title)} | ${list || 'none'} | ${info.grade ? `\`${info.grade}\`` : ''} |`;
  });
  return ['| lesson | title | exercises | grade with |', '|---|---|---|---|', ...rows].join('\n');
}

// docs/teaching.md: every `--preset NAME` in a table row whose second cell names lessons must be a
// preset of one of them.
function checkTeachingPresets(file, text, facts) {
  const problems = [];
  text.split('\n').forEach((l, i) => {
    const cells = l.split('|').map((c) => c.trim());
    if (cells.length < 4 || !/^\d\d\b/.test(cells[2] ?? '')) return;
    const lessons = facts.filter((f) => (cells[2].match(/\b\d\d\b/g) ?? []).includes(f.info.number));
    if (!lessons.length) { problems.push(`${file}:${i + 1}: no lesson ${cells[2]}`); return; }
    for (const m of l.matchAll(/--preset[ =]([A-Za-z0-9_]+)/g)) {
      if (!lessons.some((f) => f.presets.includes(m[1]))) {
        problems.push(`${file}:${i + 1}: --preset ${m[1]}: not a preset of lesson ${lessons.map((f) => f.info.number).join(' or ')}`);
      }
    }
  });
  return problems;
}

// The text between <!-- NAME: ... --> and <!-- /NAME -->, and where it starts.
function blockRange(text, name) {
  const open = new RegExp(`<!-- ${name}: [^\\n]*-->\\n`).exec(text);
  if (!open) return null;
  const start = open.index + open[0].length;
  const end = text.indexOf(`<!-- /${name} -->`, start);
  return end < 0 ? null : { start, end };
}

function fillBlock(text, name, body) {
  const r = blockRange(text, name);
  return r ? text.slice(0, r.start) + body + '\n' + text.slice(r.end) : text;
}

function lineOf(text, index) { return text.slice(0, index).split('\n').length; }

// The `##` sections of a README: [{ title, line, body }].
function sections(text) {
  const out = [];
  const lines = text.split('\n');
  let fence = false;
  lines.forEach((l, i) => {
    if (/^\s*(```|~~~)/.test(l)) fence = !fence;
    const m = fence ? null : /^## (.*?)\s*$/.exec(l);
    if (m) out.push({ title: m[1], line: i + 1, lines: [] });
    else if (out.length) out[out.length - 1].lines.push(l);
  });
  for (const s of out) s.body = s.lines.join('\n');
  return out;
}

export function checkReadme(file, text, f) {
  const problems = [];
  const at = (line, message) => problems.push(`${file}:${line}: ${message}`);
  const secs = sections(text);
  const titles = secs.map((s) => s.title);
  const expected = titles[titles.length - 1] === OPTIONAL_LAST ? [...SECTIONS, OPTIONAL_LAST] : SECTIONS;
  if (titles.join('|') !== expected.join('|')) {
    at(secs[0]?.line ?? 1, `the ## sections are [${titles.join(', ')}]; a lesson README has, in this order: ${SECTIONS.join(', ')} (then optionally ${OPTIONAL_LAST})`);
  }
  const sec = (t) => secs.find((s) => s.title === t);

  const learn = sec('What you will learn');
  if (learn) {
    const n = learn.lines.filter((l) => /^[-*] /.test(l)).length;
    if (n < 3 || n > 5) at(learn.line, `"What you will learn" has ${n} outcomes; write 3 to 5 bullets`);
  }
  const time = sec('Time and prerequisites');
  if (time) {
    const m = /\*\*Time in class:\*\*\s*(\d+) minutes/.exec(time.body);
    if (!m) at(time.line, 'no "**Time in class:** N minutes" line');
    else if (Number(m[1]) !== f.info.minutes) at(time.line, `time in class says ${m[1]} minutes; the lesson (--info) says ${f.info.minutes}`);
    const p = /\*\*Prerequisites:\*\*([^\n]*)/.exec(time.body);
    if (!p) at(time.line, 'no "**Prerequisites:**" line');
    else {
      const named = [...new Set(p[1].match(/\b\d\d\b/g) ?? [])].sort();
      const want = [...f.info.prerequisites].sort();
      if (named.join(',') !== want.join(',')) {
        at(time.line, `prerequisites name lessons [${named.join(', ')}]; the lesson (--info) says [${want.join(', ')}]`);
      }
      if (!want.length && !/\bnone\b/i.test(p[1])) at(time.line, 'no prerequisites: the line should say "none"');
    }
  }
  const passes = sec('The passes');
  if (passes) {
    const labels = passes.lines.map((l) => /^(\d+)\. |^\s+- \*\*(\d+[a-z])\.\*\*/.exec(l)).filter(Boolean).map((m) => m[1] ?? m[2]);
    if (labels.join(',') !== f.passes.join(',')) {
      at(passes.line, `the passes are numbered [${labels.join(', ')}]; main.cpp's banners are [${f.passes.join(', ')}] (one item each, "N. " or "   - **Nb.**")`);
    }
  }
  const controls = sec('Controls');
  for (const [name, make] of [['hotkeys', hotkeysBlock], ['presets', presetsBlock]]) {
    const r = blockRange(text, name);
    if (!r) { at(controls?.line ?? 1, `no generated ${name} block (<!-- ${name}: ... --> ... <!-- /${name} -->)`); continue; }
    if (text.slice(r.start, r.end) !== make(f) + '\n') at(lineOf(text, r.start), `the ${name} block is not what the lesson says now: run make docs`);
  }
  for (const p of f.presets) {
    if (p !== 'default' && !f.comments.get(p)) problems.push(`${file}:1: preset ${p} says nothing of what it shows (a comment above [${p}] in presets.txt)`);
  }
  const tryIt = sec('What to try');
  if (tryIt) {
    const bullets = tryIt.lines.map((l, i) => ({ l, line: tryIt.line + 1 + i })).filter(({ l }) => /^[-*] /.test(l));
    if (bullets.length < 3) at(tryIt.line, `"What to try" has ${bullets.length} items; write at least 3, each from a preset`);
    for (const b of bullets) if (!/^[-*] `--preset [a-z0-9_]+`/.test(b.l)) at(b.line, 'a "What to try" item starts with `--preset NAME`');
  }
  text.split('\n').forEach((l, i) => {
    for (const m of l.matchAll(/--preset[ =]([A-Za-z0-9_]+)/g)) {
      if (m[1] !== 'NAME' && !f.presets.includes(m[1])) at(i + 1, `--preset ${m[1]}: no such preset; valid: ${f.presets.join(', ')}`);
    }
    if (/ctest\b[^\n]*-L ex\d\d/.test(l)) at(i + 1, `grade with "make grade LESSON=${f.info.number}" (it builds first; ctest does not)`);
    const date = new RegExp(`\\b(\\d{1,2} )?(${MONTHS}) \\d{4}\\b`).exec(l);
    if (date) at(i + 1, `"${date[0]}": a dated figure or diary; the README states current facts (history lives in git)`);
  });
  const ex = sec('Exercises');
  if (ex) {
    for (const e of f.info.exercises) if (!ex.body.includes(e.id)) at(ex.line, `exercise ${e.id} (${e.function}) is not in "Exercises"`);
    if (f.info.exercises.length && !ex.body.includes(f.info.grade)) at(ex.line, `"Exercises" does not give the command that grades them: ${f.info.grade}`);
  }
  return problems;
}

// The keys a help text mentions, each with its line: "T:", "(T)", "(T: ...)", "T cycles", "press T".
// A digit counts only as "(1)" or "press 1": "(0: hard)" is a value.
const KEY_MENTIONS = [/\(([A-Z])[):]/g, /\((\d)\)/g, /(?:^|[.;]\s+)([A-Z]):/g, /[Pp]ress ([A-Z0-9])\b/g,
  /(?:^|[.;]\s+)([A-Z]) (?:cycles|toggles|turns|steps|switches)\b/g];

export function checkHelp(file, text, f) {
  const problems = [];
  const bound = new Map(f.hotkeys.map(([key, param]) => [key, param]));
  text.split('\n').forEach((line, i) => {
    const keys = new Set();
    for (const re of KEY_MENTIONS) for (const m of line.matchAll(re)) keys.add(m[1]);
    for (const k of keys) {
      const param = bound.get(k);
      if (!param) {
        const taken = f.framework.includes(k) ? ` (${k} is the framework's)` : '';
        problems.push(`${file}:${i + 1}: the help names key ${k}, which drives nothing in this lesson${taken}; ` +
          `its keys: ${[...bound].map(([key, p]) => `${key} ${p}`).join(', ')}`);
      } else if (!line.includes(param)) {
        problems.push(`${file}:${i + 1}: the help names key ${k}, which drives ${param}; the line does not name ${param}`);
      }
    }
  });
  return problems;
}

function main() {
  const o = parseArgs(process.argv.slice(2));
  const names = o.lesson ? [o.lesson]
    : fs.readdirSync(path.join(o.root, 'lessons')).filter((d) => /^\d\d_/.test(d)).sort();
  let facts;
  try { facts = names.map((n) => lessonFacts(o.root, o.bin, n)); } catch (e) { console.error(`lesson_docs: ${e.message}`); process.exit(1); }
  const problems = [];
  if (o.helpText) {
    problems.push(...checkHelp(path.relative(process.cwd(), o.helpText), fs.readFileSync(o.helpText, 'utf8'), facts[0]));
    for (const p of problems) console.log(p);
    console.log(problems.length ? `lesson_docs: ${problems.length} problem(s)` : 'lesson_docs: the help text names its keys right');
    process.exit(problems.length ? 1 : 0);
  }
  for (const f of facts) problems.push(...checkHelp(`lesson_${f.name} --info help`, f.info.help, f));
  const files = facts.map((f) => ({ f, file: o.readme ?? path.join(o.root, 'lessons', f.name, 'README.md') }));
  if (!o.lesson) {
    files.push({ top: 'lessons', file: path.join(o.root, 'README.md') });
    files.push({ top: 'assignments', file: path.join(o.root, 'docs', 'teaching.md') });
  }
  for (const { f, file, top } of files) {
    const rel = path.relative(process.cwd(), file) || file;
    const text = fs.readFileSync(file, 'utf8');
    let want = text;
    if (top) want = fillBlock(text, top, (top === 'lessons' ? lessonsBlock : assignmentsBlock)(facts));
    else for (const [name, make] of [['hotkeys', hotkeysBlock], ['presets', presetsBlock]]) want = fillBlock(want, name, make(f));
    if (o.mode === 'write') {
      if (want !== text) { fs.writeFileSync(file, want); console.log(`lesson_docs: wrote ${rel}`); }
      continue;
    }
    if (top) {
      const r = blockRange(text, top);
      if (!r) problems.push(`${rel}:1: no generated ${top} block (<!-- ${top}: ... --> ... <!-- /${top} -->)`);
      else if (want !== text) problems.push(`${rel}:${lineOf(text, r.start)}: the ${top} table is not what the lessons say now: run make docs`);
      if (top === 'assignments') problems.push(...checkTeachingPresets(rel, text, facts));
    } else {
      problems.push(...checkReadme(rel, text, f));
    }
  }
  for (const p of problems) console.log(p);
  if (o.mode === 'check') console.log(problems.length ? `lesson_docs: ${problems.length} problem(s)` : `lesson_docs: ${files.length} README(s) in order`);
  process.exit(problems.length ? 1 : 0);
}

main();
