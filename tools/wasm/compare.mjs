// compare.mjs: what the web checks share. A console line that reports a WebGL error, and two PNG
// pictures compared in a browser page (Chromium decodes them): the share
// (percent) of pixels whose largest channel differs by more than `levels`, and the largest
// difference. check.mjs (a lesson's page against the native lesson) and check_slides.mjs (a live
// figure against its still) use it. block > 1 compares the means of block x block squares: two
// resamplings of one picture (a still scaled as an image, a canvas scaled as a page) differ pixel
// by pixel in fine texture, not in what the picture shows.
export async function comparePngs(page, a, b, levels, block = 1) {
  const urls = [a, b].map((png) => 'data:image/png;base64,' + Buffer.from(png).toString('base64'));
  return page.evaluate(async ({ urls, levels, block }) => {
    const pixels = await Promise.all(urls.map(async (u) => {
      const img = new Image();
      img.src = u;
      await img.decode();
      const c = document.createElement('canvas');
      c.width = img.width;
      c.height = img.height;
      const g = c.getContext('2d');
      g.drawImage(img, 0, 0);
      return { w: img.width, h: img.height, d: g.getImageData(0, 0, img.width, img.height).data };
    }));
    if (pixels[0].w !== pixels[1].w || pixels[0].h !== pixels[1].h) {
      return { error: `sizes differ: ${pixels[0].w}x${pixels[0].h} against ${pixels[1].w}x${pixels[1].h}` };
    }
    const mean = (p) => {
      if (block <= 1) return p;
      const w = Math.floor(p.w / block), h = Math.floor(p.h / block), d = new Float32Array(w * h * 4);
      for (let y = 0; y < h * block; ++y)
        for (let x = 0; x < w * block; ++x)
          for (let c = 0; c < 3; ++c) d[((Math.floor(y / block) * w) + Math.floor(x / block)) * 4 + c] += p.d[(y * p.w + x) * 4 + c] / (block * block);
      return { w, h, d };
    };
    const [x, y] = pixels.map(mean);
    let over = 0, worst = 0;
    for (let i = 0; i < x.d.length; i += 4) {
      const d = Math.max(Math.abs(x.d[i] - y.d[i]), Math.abs(x.d[i + 1] - y.d[i + 1]), Math.abs(x.d[i + 2] - y.d[i + 2]));
      worst = Math.max(worst, d);
      if (d > levels) ++over;
    }
    return { percent: (100 * over) / (x.w * x.h), worst };
  }, { urls, levels, block });
}

// Whether a page's console line reports a WebGL or shader error. Chromium's advice when a page
// enables WEBGL_polygon_mode (lesson 04's wireframe, behind gl::caps().polygonMode) is not one.
export function webglError(text) {
  if (/^WebGL: this extension has very low support on mobile devices.*: WEBGL_polygon_mode$/.test(text)) return false;
  return /WebGL: |GL error|INVALID_|shader.*(error|failed)/i.test(text);
}
