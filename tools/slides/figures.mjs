// Figures rendered by the lessons themselves: `lesson:NN_name?preset=P&set=k=v&size=WxH&frames=N&zoom=X,Y,W&live=a,b`
// runs build/<preset>/bin/lesson_NN_name --headless ... --screenshot FILE.png. PNGs are cached by a
// hash of the command line and the binary's size and mtime, so an unchanged lesson is not re-run and
// a rebuilt one always is. A failed render fails the build with the lesson's own message.
import { execFile } from 'node:child_process';
import { createHash } from 'node:crypto';
import fs from 'node:fs';
import path from 'node:path';

export const DEFAULT_SIZE = '960x540';
export const DEFAULT_FRAMES = 3;
const TIMEOUT_MS = 120_000;

export class FigureError extends Error {}

// A live figure's page in the browser build's site (the decks sit in site/slides, the lessons'
// pages beside that folder): the lesson at the figure's preset, sets, size and panel.
export function livePage(spec) {
  const q = [`preset=${encodeURIComponent(spec.preset)}`, ...spec.sets.map((s) => `set=${encodeURIComponent(s)}`),
    `size=${spec.size}`, `panel=${spec.live.join(',')}`];
  return `../lesson_${spec.lesson}.html?${q.join('&')}`;
}

// "lesson:01_lighting?preset=three_lights&set=a=1&size=640x360" -> spec (throws on bad syntax).
export function parseFigureUrl(url) {
  const m = /^lesson:(\d\d_[a-z0-9_]+)(?:\?(.*))?$/.exec(url);
  if (!m) throw new FigureError(`figure "${url}": expected lesson:NN_name?preset=NAME`);
  const spec = { lesson: m[1], preset: null, sets: [], size: DEFAULT_SIZE, frames: DEFAULT_FRAMES };
  for (const part of (m[2] ?? '').split('&').filter(Boolean)) {
    const eq = part.indexOf('=');
    const key = eq < 0 ? part : part.slice(0, eq);
    const value = eq < 0 ? '' : decodeURIComponent(part.slice(eq + 1));
    if (key === 'preset') spec.preset = value;
    else if (key === 'set') {
      if (!/^[^=\s]+=./.test(value)) throw new FigureError(`figure "${url}": set=${value} is not name=value`);
      spec.sets.push(value);
    } else if (key === 'size') {
      if (!/^\d{2,5}x\d{2,5}$/.test(value)) throw new FigureError(`figure "${url}": size=${value} is not WxH`);
      spec.size = value;
    } else if (key === 'frames') {
      if (!/^[1-9]\d{0,3}$/.test(value)) throw new FigureError(`figure "${url}": frames=${value} is not a positive count`);
      spec.frames = Number(value);
    } else if (key === 'zoom') {
      // zoom=X,Y,W: show only the region of the figure from (X, Y) (fractions of its width and
      // height from the top left), W of its width wide and W of its height high, enlarged to the
      // figure's size: where two pictures of a comparison differ (the lesson renders it whole).
      const z = value.split(',').map(Number);
      if (z.length !== 3 || z.some((v) => !Number.isFinite(v)) || z[2] <= 0 || z[2] > 1 || z[0] < 0 || z[1] < 0 ||
          z[0] + z[2] > 1 + 1e-9 || z[1] + z[2] > 1 + 1e-9) {
        throw new FigureError(`figure "${url}": zoom=${value} is not X,Y,W with 0 < W <= 1, X + W <= 1 and Y + W <= 1`);
      }
      spec.zoom = { x: z[0], y: z[1], w: z[2] };
    } else if (key === 'live') {
      // live=a,b: the deck shows the lesson's page in the slide instead (where the site has it and the
      // browser WebGL2), with the parameter panel open on these parameters only (--panel); the still,
      // rendered with the same panel, stays underneath for the PDF and for browsers without WebGL2.
      if (!/^[a-z0-9_.]+(,[a-z0-9_.]+)*$/.test(value)) throw new FigureError(`figure "${url}": live=${value} is not NAME,NAME (the parameters its panel shows)`);
      spec.live = value.split(',');
    } else throw new FigureError(`figure "${url}": unknown option "${key}" (preset, set, size, frames, zoom, live)`);
  }
  if (spec.live && spec.zoom) throw new FigureError(`figure "${url}": live and zoom together: a live figure shows the whole lesson`);
  if (!spec.preset) throw new FigureError(`figure "${url}": needs preset=NAME (a figure always names a lesson preset)`);
  return spec;
}

function run(binary, args) {
  return new Promise((resolve) => {
    execFile(binary, args, { timeout: TIMEOUT_MS, maxBuffer: 16 << 20 }, (error, stdout, stderr) => {
      resolve({ code: error ? (error.code ?? error.signal ?? 1) : 0, stdout, stderr, error });
    });
  });
}

function lastLines(text, n = 3) {
  return text.trim().split('\n').slice(-n).join('\n') || '(no output)';
}

export class FigureRenderer {
  constructor({ binDir, outDir, jobs }) {
    this.binDir = binDir;
    this.outDir = outDir; // figures go to outDir/figures
    this.jobs = Math.max(1, jobs);
    this.lessons = new Map(); // lesson name -> Promise<{binary, stat, presets, info}>
    this.stats = { rendered: 0, cached: 0 };
    this.queue = [];
    this.active = 0;
    this.inflight = new Map(); // figure file -> Promise of its render: one run per figure, however often used
  }

  binaryFor(lesson) {
    return path.join(this.binDir, `lesson_${lesson}`);
  }

  // What the lesson says about itself (--info, --list-presets); once per lesson per build.
  lesson(lesson) {
    if (!this.lessons.has(lesson)) this.lessons.set(lesson, this.#probe(lesson));
    return this.lessons.get(lesson);
  }

  async #probe(lesson) {
    const binary = this.binaryFor(lesson);
    let stat;
    try {
      stat = fs.statSync(binary);
    } catch {
      throw new FigureError(`lesson binary ${binary} does not exist: build the lessons first ` +
        `(cmake --build --preset default) or pass --bin DIR`);
    }
    const list = await run(binary, ['--list-presets']);
    if (list.code !== 0) throw new FigureError(`${binary} --list-presets failed (exit ${list.code}): ${lastLines(list.stderr || list.stdout)}`);
    const presets = list.stdout.split('\n').map((s) => s.trim()).filter(Boolean);
    const infoRun = await run(binary, ['--info']);
    if (infoRun.code !== 0) throw new FigureError(`${binary} --info failed (exit ${infoRun.code}): ${lastLines(infoRun.stderr || infoRun.stdout)}`);
    let info;
    try {
      info = JSON.parse(infoRun.stdout.trim().split('\n').pop());
    } catch (e) {
      throw new FigureError(`${binary} --info did not print one JSON object: ${lastLines(infoRun.stdout)}`);
    }
    return { binary, stat, presets, info };
  }

  args(spec, file) {
    const args = ['--headless', '--size', spec.size, '--frames', String(spec.frames), '--preset', spec.preset];
    for (const s of spec.sets) args.push('--set', s);
    if (spec.live) args.push('--panel', spec.live.join(','));
    return file ? [...args, '--screenshot', file] : args;
  }

  // Renders (or reuses) one figure; resolves to its path relative to outDir.
  async render(spec) {
    const { binary, stat, presets } = await this.lesson(spec.lesson);
    if (!presets.includes(spec.preset)) {
      throw new FigureError(`lesson ${spec.lesson} has no preset "${spec.preset}"; it has: ${presets.join(', ')}`);
    }
    const key = createHash('sha256')
      .update(JSON.stringify([path.basename(binary), this.args(spec), stat.size, stat.mtimeMs]))
      .digest('hex').slice(0, 16);
    const name = `${spec.lesson}-${spec.preset}-${key}.png`;
    const rel = `figures/${name}`;
    const file = path.join(this.outDir, rel);
    if (isPng(file)) {
      this.stats.cached++;
      return rel;
    }
    // The same figure twice in a build (a zoom of a figure shown whole too) renders once: two runs
    // wrote the same temporary file, and one found it gone ("exit 0 but no PNG written").
    if (!this.inflight.has(file)) this.inflight.set(file, this.#renderTo(spec, binary, file, rel));
    return this.inflight.get(file);
  }

  async #renderTo(spec, binary, file, rel) {
    await this.#slot();
    try {
      fs.mkdirSync(path.dirname(file), { recursive: true });
      const tmp = `${file}.${process.pid}.tmp.png`;
      const r = await run(binary, this.args(spec, tmp));
      if (r.code !== 0 || !isPng(tmp)) {
        fs.rmSync(tmp, { force: true });
        const cmd = [path.relative(process.cwd(), binary), ...this.args(spec, 'FILE.png')].join(' ');
        const why = r.code !== 0 ? `exit ${r.code}` : 'exit 0 but no PNG written';
        throw new FigureError(`figure ${spec.lesson}?preset=${spec.preset} failed (${why}): ${cmd}\n  ${lastLines(r.stderr || r.stdout).replace(/\n/g, '\n  ')}`);
      }
      fs.renameSync(tmp, file);
      this.stats.rendered++;
      return rel;
    } finally {
      this.#release();
    }
  }

  #slot() {
    if (this.active < this.jobs) { this.active++; return Promise.resolve(); }
    return new Promise((resolve) => this.queue.push(resolve));
  }

  #release() {
    const next = this.queue.shift();
    if (next) next(); else this.active--;
  }

  // Removes cached figures that no deck of this build used (keeps out/ from growing forever).
  prune(used) {
    const dir = path.join(this.outDir, 'figures');
    if (!fs.existsSync(dir)) return 0;
    let removed = 0;
    for (const f of fs.readdirSync(dir)) {
      if (!used.has(`figures/${f}`)) { fs.rmSync(path.join(dir, f), { force: true }); removed++; }
    }
    return removed;
  }
}

function isPng(file) {
  try {
    const fd = fs.openSync(file, 'r');
    const buf = Buffer.alloc(8);
    const n = fs.readSync(fd, buf, 0, 8, 0);
    fs.closeSync(fd);
    return n === 8 && buf.equals(Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]));
  } catch {
    return false;
  }
}
