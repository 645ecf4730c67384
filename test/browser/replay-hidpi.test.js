// Loads an afrp replay page in headless Chromium on a screen of 2 device
// pixels a CSS pixel (1200 by 800 CSS pixels) and checks that the canvas
// has the screen's pixels, shown at the size it has on a screen of 1:
//   node replay-hidpi.test.js PAGE.html
// The page must be that of the test fixture (test/AFrobRobotSim/LogFixture.hs):
// SimbotA 1 and SimbotB 2 in the notes' 10 m world. Checked: the canvas
// is 640 CSS pixels wide and has twice as many pixels; worldToCanvas and
// canvasToWorld are in the canvas's pixels (a robot's colour is read where
// worldToCanvas puts it, and a click there, in CSS pixels, selects it);
// the zoom's limit is still 250 CSS pixels a metre; the ids are drawn at
// 12 CSS pixels (24 of the canvas's).
// Chromium: $CHROMIUM, else /usr/bin/chromium. Exits 0 when every check
// passes, 1 with the failures listed otherwise.
'use strict';
const { run, check, near } = require('./harness');

run('node replay-hidpi.test.js PAGE.html', async (page, errors, open) => {
    await open();
    const info = await page.evaluate(() => {
      const c = document.getElementById('world'), r = c.getBoundingClientRect(), R = window.afrpReplay;
      return { dpr: window.devicePixelRatio, width: c.width, height: c.height, css: c.clientWidth, cssHeight: c.clientHeight,
               inner: [r.left + c.clientLeft, r.top + c.clientTop], scale: R.worldToCanvas(1, 0)[0] - R.worldToCanvas(0, 0)[0],
               maxZoom: R.maxZoom, robots: R.header.robots, first: R.frameData(0).robots };
    });
    check(info.dpr === 2, 'the screen has 2 device pixels a CSS pixel (' + info.dpr + ')');
    check(info.css === 640 && info.cssHeight === 640, 'the canvas is shown 640 by 640 CSS pixels, as on a screen of 1 (' +
          info.css + ' by ' + info.cssHeight + ')');
    check(info.width === 1280 && info.height === 1280, 'and has 1280 by 1280 pixels, the screen\'s (' + info.width + ' by ' + info.height + ')');
    check(Math.abs(info.scale - 124) < 1e-9, 'worldToCanvas is in the canvas\'s pixels: 124 a metre (' + info.scale + ')');
    // (CSS pixels a canvas pixel: the canvas as shown)
    const cssPx = info.css / info.width;
    check(Math.abs(info.maxZoom * info.scale * cssPx - 250) < 1e-9, 'the zoom still stops at 250 CSS pixels a metre (' +
          (info.maxZoom * info.scale * cssPx) + ')');
    const round = await page.evaluate(() => { const R = window.afrpReplay, p = R.worldToCanvas(1.25, -3.5); return R.canvasToWorld(p[0], p[1]); });
    check(near(round, [1.25, -3.5], 1e-9), 'canvasToWorld undoes worldToCanvas (' + JSON.stringify(round) + ')');

    // each robot's colour where worldToCanvas puts it (behind its centre: the heading mark runs forward)
    const colourAt = (r, k) => page.evaluate(([r, k]) => {
      const R = window.afrpReplay, p = R.worldToCanvas(r.x - k * Math.cos(r.heading), r.y - k * Math.sin(r.heading));
      return Array.from(document.getElementById('world').getContext('2d').getImageData(Math.round(p[0]), Math.round(p[1]), 1, 1).data.slice(0, 3));
    }, [r, k]);
    const half = info.robots[0].radius / 2;
    const a = await colourAt(info.first[0], half), bB = await colourAt(info.first[1], half);
    check(near(a, [30, 90, 220], 2) && near(bB, [215, 40, 40], 2), 'SimbotA 1 and SimbotB 2 are drawn where worldToCanvas puts them (' +
          JSON.stringify([a, bB]) + ')');

    // a click at SimbotB 2, in CSS pixels
    const pB = await page.evaluate(r => window.afrpReplay.worldToCanvas(r.x - 0.1 * Math.cos(r.heading), r.y - 0.1 * Math.sin(r.heading)), info.first[1]);
    await page.mouse.click(info.inner[0] + pB[0] * cssPx, info.inner[1] + pB[1] * cssPx);
    check(await page.evaluate(() => window.afrpReplay.selected()) === 1, 'a click on SimbotB 2 selects it');

    // the ids' font, caught as they are drawn
    const fonts = await page.evaluate(() => {
      const proto = CanvasRenderingContext2D.prototype, fillText = proto.fillText, fonts = [];
      proto.fillText = function () { fonts.push(this.font); return fillText.apply(this, arguments); };
      try { window.afrpReplay.setFrame(1); } finally { proto.fillText = fillText; }
      return fonts;
    });
    check(fonts.length === 2 && fonts.every(f => f.startsWith('24px')), 'the ids are drawn 24 canvas pixels high (' + fonts.join(', ') + ')');
    check(errors.length === 0, 'no errors on the page' + (errors.length ? ': ' + errors.join('; ') : ''));
}, { deviceScaleFactor: 2 });
