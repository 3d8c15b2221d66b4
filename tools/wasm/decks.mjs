// decks.mjs: the site's decks and their live figures (tools/slides, live=...), for check_slides.mjs
// (the test) and bench.mjs (the figures).
import fs from 'node:fs';
import path from 'node:path';

// The decks of SITE/slides: NN_name.html.
export function siteDecks(site) {
  const dir = path.join(site, 'slides');
  return fs.existsSync(dir) ? fs.readdirSync(dir).filter((f) => /^\d\d_[a-z0-9_]+\.html$/.test(f)).sort() : [];
}

// In an open deck: [slide index, live figures] for each slide that holds live figures.
export const liveSlides = (p) =>
  p.evaluate(() => Reveal.getSlides().map((s, i) => [i, s.querySelectorAll('.live').length]).filter(([, n]) => n > 0));

// Waits until each of the current slide's `count` live figures has a page that drew `frames`
// frames; returns the time of the first of them from the deck's navigation (ms).
export async function liveFrames(p, count, frames = 3) {
  await p.waitForFunction(([n, k]) => {
    const pages = [...Reveal.getCurrentSlide().querySelectorAll('.live')].map((b) => b.querySelector('iframe'));
    return pages.length === n && pages.every((f) => f && f.contentWindow && f.contentWindow.shadowlab &&
      (f.contentWindow.shadowlab.frameTimes || []).length >= k);
  }, [count, frames], { timeout: 120000 });
  return p.evaluate(() => Math.min(...[...Reveal.getCurrentSlide().querySelectorAll('.live iframe')].map((f) =>
    f.contentWindow.performance.timeOrigin + f.contentWindow.shadowlab.firstFrameMs - performance.timeOrigin)));
}
