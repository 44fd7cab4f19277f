// Paints the error masks of `recode conform --html`'s page (conformance/src/report.cpp writes
// the page and embeds this file at build time). Each canvas.mask carries its frame's pixels in
// buffer order, bottom row first, as runs "code:count" in data-runs: code -1 is a good pixel
// (white), code k a bad one coloured by the k-th colour of the body's data-stage-colours (the
// stages in order, then the colour of a pixel that was not explained).
'use strict';
const colours = document.body.dataset.stageColours.trim().split(' ');
for (const c of document.querySelectorAll('canvas.mask')) {
  const g = c.getContext('2d'), w = c.width, h = c.height;
  g.fillStyle = '#fff';
  g.fillRect(0, 0, w, h);
  let i = 0;
  for (const run of c.dataset.runs.trim().split(' ')) {
    if (!run) continue;
    const [code, n] = run.split(':').map(Number);
    if (code >= 0) {
      g.fillStyle = colours[code];
      // The canvas's rows run top down; the buffer's bottom row is its last.
      for (let k = i; k < i + n; ++k) g.fillRect(k % w, h - 1 - Math.floor(k / w), 1, 1);
    }
    i += n;
  }
}
