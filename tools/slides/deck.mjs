// Deck source -> slides -> HTML. A deck is Markdown: front matter between two `---` lines at the
// top, then slides separated by lines that are exactly `---` (outside fenced code). Formulas in
// $...$ and $$...$$ become KaTeX HTML here, at build time, so the browser needs no script for them.
// Figures `![caption](lesson:NN_name?preset=P)` are collected here and rendered by figures.mjs.
import { katex, Marked } from './deps.mjs';

export class DeckError extends Error {
  constructor(file, line, message) {
    super(`${file}${line ? `:${line}` : ''}: ${message}`);
  }
}

const SEPARATOR = /^---[ \t]*$/;
const FENCE = /^ {0,3}(`{3,}|~{3,})/;

// Front matter: `key: value` lines. Required keys: lesson (NN_name) and title.
export function parseDeck(source, file) {
  const lines = source.replace(/\r\n?/g, '\n').split('\n');
  if (!SEPARATOR.test(lines[0] ?? '')) {
    throw new DeckError(file, 1, 'a deck starts with front matter: ---, lesson: NN_name, title: ..., ---');
  }
  const meta = {};
  let i = 1;
  for (; i < lines.length && !SEPARATOR.test(lines[i]); i++) {
    if (!lines[i].trim() || lines[i].trimStart().startsWith('#')) continue;
    const m = /^([A-Za-z_][\w-]*)\s*:\s*(.*?)\s*$/.exec(lines[i]);
    if (!m) throw new DeckError(file, i + 1, `front matter line is not "key: value": ${lines[i]}`);
    meta[m[1]] = m[2].replace(/^(["'])(.*)\1$/, '$2');
  }
  if (i >= lines.length) throw new DeckError(file, 1, 'front matter is not closed by a --- line');
  for (const key of ['lesson', 'title']) {
    if (!meta[key]) throw new DeckError(file, 1, `front matter needs "${key}:"`);
  }
  if (!/^\d\d_[a-z0-9_]+$/.test(meta.lesson)) {
    throw new DeckError(file, 1, `lesson "${meta.lesson}" is not a lesson folder name like 01_lighting`);
  }

  // Slides: split on separator lines that are not inside fenced code.
  const slides = [];
  let current = [], startLine = i + 2, fence = null;
  for (i = i + 1; i < lines.length; i++) {
    const line = lines[i];
    const f = FENCE.exec(line);
    if (f) {
      if (!fence) fence = f[1][0].repeat(f[1].length);
      else if (line.trim().startsWith(fence)) fence = null;
    }
    if (!fence && SEPARATOR.test(line)) {
      slides.push({ markdown: current.join('\n'), line: startLine });
      current = [];
      startLine = i + 2;
    } else {
      current.push(line);
    }
  }
  slides.push({ markdown: current.join('\n'), line: startLine });
  if (fence) throw new DeckError(file, 0, `unclosed code fence ${fence}`);
  slides.forEach((s, n) => {
    if (!s.markdown.trim()) throw new DeckError(file, s.line, `slide ${n + 1} is empty (two --- in a row, or a --- at the end?)`);
    // Speaker notes: everything after a line starting with "Note:" (reveal.js convention).
    const notes = /^Notes?:[ \t]*/im.exec(s.markdown);
    if (notes) {
      s.notes = s.markdown.slice(notes.index + notes[0].length);
      s.markdown = s.markdown.slice(0, notes.index);
    }
  });
  return { meta, slides };
}

export function escapeHtml(s) {
  return String(s).replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' })[c]);
}

// One KaTeX call for every formula. throwOnError:false leaves a .katex-error node in the page
// (which the page check fails on); the builder also reports it so the author sees it at once.
function renderMath(tex, displayMode, ctx) {
  const html = katex.renderToString(tex, { displayMode, throwOnError: false, output: 'htmlAndMathml', strict: 'ignore' });
  if (html.includes('katex-error')) ctx.mathErrors.push(tex);
  return html;
}

// Markdown with math and figures. ctx collects what the slide needs from outside:
//   ctx.figures   image tokens whose href starts with "lesson:" (href is rewritten later)
//   ctx.images    other local images to copy next to the deck
//   ctx.mathErrors formulas KaTeX could not parse
// A figure's image; with zoom (figures.mjs) only its region, enlarged, in a box of the figure's
// size and aspect that clips the rest (CSS only: the PNG stays whole, and so does its cache).
// A live figure (live=...): the image in a box the deck's script puts the lesson's page over.
function figureImage(t) {
  const img = `<img src="${escapeHtml(t.href)}" alt="${escapeHtml(t.text)}">`;
  if (t.live) return `<span class="live" data-page="${escapeHtml(t.live.page)}" data-size="${t.live.size}">${img}</span>`;
  const z = t.zoom;
  if (!z) return img;
  const [w, h] = z.size.split('x').map(Number);
  const style = `width:${w}px;aspect-ratio:${w}/${h};--zx:${z.x};--zy:${z.y};--zw:${z.w}`;
  return `<span class="zoom" style="${style}" title="enlarged ${(1 / z.w).toFixed(1)}x">${img}</span>`;
}

export function makeMarkdown() {
  const md = new Marked({ gfm: true, breaks: false });
  let ctx = null;
  md.use({
    extensions: [
      {
        name: 'blockMath',
        level: 'block',
        start(src) { const m = /^ {0,3}\$\$/m.exec(src); return m ? m.index : undefined; },
        tokenizer(src) {
          const m = /^ {0,3}\$\$([\s\S]+?)\$\$[ \t]*(?:\n+|$)/.exec(src);
          if (m) return { type: 'blockMath', raw: m[0], text: m[1].trim() };
          return undefined;
        },
        renderer(token) { return `<div class="math-display">${renderMath(token.text, true, ctx)}</div>\n`; },
      },
      {
        name: 'inlineMath',
        level: 'inline',
        start(src) { const i = src.indexOf('$'); return i < 0 ? undefined : i; },
        tokenizer(src) {
          let m = /^\$\$([\s\S]+?)\$\$/.exec(src);
          if (m) return { type: 'inlineMath', raw: m[0], text: m[1].trim(), display: true };
          m = /^\$(?![\s$])((?:\\.|[^\\$\n])+?)(?<!\s)\$(?!\d)/.exec(src);
          if (m) return { type: 'inlineMath', raw: m[0], text: m[1], display: false };
          return undefined;
        },
        renderer(token) { return renderMath(token.text, token.display, ctx); },
      },
    ],
    renderer: {
      // A paragraph made only of images is a figure row: one image = one figure, two or more =
      // side by side at equal width (acne | biased).
      paragraph(token) {
        const items = token.tokens.filter((t) => !(t.type === 'text' && !t.text.trim()) && t.type !== 'br');
        if (items.length && items.every((t) => t.type === 'image')) {
          const figs = items.map((t) => {
            const caption = t.tokens?.length ? this.parser.parseInline(t.tokens) : escapeHtml(t.text);
            return `<figure>${figureImage(t)}` + (t.text.trim() ? `<figcaption>${caption}</figcaption>` : '') + '</figure>';
          });
          return `<div class="figrow figrow-${figs.length}">${figs.join('')}</div>\n`;
        }
        // A paragraph that is only a citation, "([Tarantsev-L12], illumination with visibility)" (keys
        // of docs/references.md), is set small under the formula it cites.
        const cls = /^\(\[[A-Za-z][\w-]*\][^\n]*\)$/.test(token.text.trim()) ? ' class="cite"' : '';
        return `<p${cls}>${this.parser.parseInline(token.tokens)}</p>\n`;
      },
      image(token) {
        return `<img src="${escapeHtml(token.href)}" alt="${escapeHtml(token.text)}">`;
      },
    },
  });
  return {
    // Lex a slide; returns tokens plus the image tokens the caller must resolve before render().
    lex(markdown) {
      const tokens = md.lexer(markdown);
      const images = [];
      md.walkTokens(tokens, (t) => { if (t.type === 'image') images.push(t); });
      return { tokens, images };
    },
    render(tokens, slideCtx) {
      ctx = slideCtx;
      try { return md.parser(tokens); } finally { ctx = null; }
    },
  };
}

// Generated slide content, so a deck cannot drift from its lesson. A line that is exactly
//   {{passes}}     becomes the numbered passes of the lesson's main.cpp (its `// ==== N. title` banners)
//   {{exercises}}  becomes the table of the lesson's exercises (`lesson --info`: id, function, file)
//                  and the command that grades them
// Any other {{...}} line is an error naming it and the valid ones.
export const GENERATED = ['passes', 'exercises'];
const DIRECTIVE = /^\{\{\s*([a-z_]*)\s*\}\}[ \t]*$/;

export function usesGenerated(slides) {
  return slides.some((s) => s.markdown.split('\n').some((l) => DIRECTIVE.test(l)));
}

// The banners of a lesson's main.cpp: [{ label: '1b', title: '...' }], in source order.
export function passesOf(mainSource) {
  const out = [];
  for (const line of mainSource.split('\n')) {
    const m = /^\s*\/\/ ==== (\d+[a-z]?)\. (.*?)\s*=*\s*$/.exec(line);
    if (m) out.push({ label: m[1], title: m[2] });
  }
  return out;
}

function passesMarkdown(passes) {
  // A sub-pass ("1b") is a nested item under its pass.
  return passes.map((p) => (/^\d+$/.test(p.label) ? `${p.label}. ${p.title}` : `    - **${p.label}.** ${p.title}`)).join('\n');
}

function exercisesMarkdown(info) {
  const rows = info.exercises.map((e) => `| ${e.id} | \`${e.function}\` | \`${e.file}\` |`);
  return ['| exercise | function | write it in |', '|---|---|---|', ...rows, '', `Grade: \`${info.grade}\``].join('\n');
}

export function expandGenerated(slides, { passes, info }, file) {
  for (const s of slides) {
    s.markdown = s.markdown.split('\n').map((line, k) => {
      const m = DIRECTIVE.exec(line);
      if (!m) return line;
      if (m[1] === 'passes') {
        if (!passes.length) throw new DeckError(file, s.line + k, '{{passes}}: the lesson\'s main.cpp has no "// ==== N. title" banners');
        return passesMarkdown(passes);
      }
      if (m[1] === 'exercises') {
        if (!info?.exercises?.length) throw new DeckError(file, s.line + k, '{{exercises}}: the lesson has no exercises (--info)');
        return exercisesMarkdown(info);
      }
      throw new DeckError(file, s.line + k, `unknown generated block {{${m[1]}}}; valid: ${GENERATED.map((g) => `{{${g}}}`).join(', ')}`);
    }).join('\n');
  }
}
