// Loads an afrp replay page in headless Chromium (1200 by 800, 1 device
// pixel a CSS pixel) and checks that the canvas follows the screen's
// ratio of pixels when it changes after the page opened, as the browser's
// zoom changes it (and the window's size in CSS pixels with it):
//   node replay-rescale.test.js PAGE.html
// The page must be that of the test fixture (test/AFrobRobotSim/LogFixture.hs):
// SimbotA 1 and SimbotB 2 in the notes' 10 m world. The ratio and the
// window are changed through the DevTools protocol
// (Emulation.setDeviceMetricsOverride), as a zoom of 200%, 150%, 50%
// and back to 100%. (The ratio changed alone, as when the window is taken
// to another screen, is not tried: emulated, it fires neither a resize nor
// the media query's change, which a real screen's change does.) Checked at each: the canvas has the ratio's pixels
// (at least 1 and at most 2 a CSS pixel) and is still shown 640 CSS
// pixels wide (or scaled to fit the window); worldToCanvas is in its pixels (a robot's colour is read
// where it puts it, and a click there selects it); the view (zoom and
// middle) and the frame are kept; a resize that keeps the ratio keeps the
// canvas and gives no canvas a width; one listener of a media query is
// live at the end (each change's is removed).
// Chromium: $CHROMIUM, else /usr/bin/chromium. Exits 0 when every check
// passes, 1 with the failures listed otherwise.
'use strict';
const { run, check, near } = require('./harness');

run('node replay-rescale.test.js PAGE.html', async (page, errors, open) => {
    // (counted before the page's script runs: the media queries' change
    // listeners live, and how often a canvas is given a width)
    await page.addInitScript(() => {
      window.afrpSpy = { listeners: 0, widths: 0 };
      const MQ = window.MediaQueryList.prototype, add = MQ.addEventListener, remove = MQ.removeEventListener;
      MQ.addEventListener = function (type, f, o) { if (type === 'change') window.afrpSpy.listeners++; return add.call(this, type, f, o); };
      MQ.removeEventListener = function (type, f, o) { if (type === 'change') window.afrpSpy.listeners--; return remove.call(this, type, f, o); };
      const width = Object.getOwnPropertyDescriptor(HTMLCanvasElement.prototype, 'width');
      Object.defineProperty(HTMLCanvasElement.prototype, 'width', {
        get: function () { return width.get.call(this); },
        set: function (v) { window.afrpSpy.widths++; width.set.call(this, v); },
        configurable: true });
    });
    const spy = () => page.evaluate(() => Object.assign({}, window.afrpSpy));
    await open();
    const cdp = await page.context().newCDPSession(page);
    // a zoom of the browser: the ratio times z, the window's CSS pixels over z
    const zoom = async z => {
      await cdp.send('Emulation.setDeviceMetricsOverride',
                     { width: Math.round(1200 / z), height: Math.round(800 / z), deviceScaleFactor: z, mobile: false });
      // (the page's listeners run before the next animation frame's callbacks)
      await page.evaluate(() => new Promise(done => requestAnimationFrame(() => requestAnimationFrame(done))));
    };
    const state = () => page.evaluate(() => {
      const c = document.getElementById('world'), R = window.afrpReplay, r = c.getBoundingClientRect();
      return { dpr: window.devicePixelRatio, width: c.width, height: c.height, css: c.clientWidth, cssHeight: c.clientHeight,
               inner: [r.left + c.clientLeft, r.top + c.clientTop], view: R.view(), frame: R.frame(),
               scale: R.worldToCanvas(1, 0)[0] - R.worldToCanvas(0, 0)[0], middle: R.worldToCanvas(R.view().cx, R.view().cy),
               robots: R.frameData().robots, radius: R.header.robots[0].radius, page: document.documentElement.clientWidth };
    });
    const start = await state();
    check(start.dpr === 1 && start.width === 640 && start.height === 640 && start.css === 640,
          'at first the canvas has 640 by 640 pixels, shown 640 CSS pixels wide (' + JSON.stringify([start.dpr, start.width, start.css]) + ')');
    // a frame and a view of the user's, which a zoom keeps
    await page.evaluate(() => { window.afrpReplay.setFrame(12); window.afrpReplay.setView(1.5, -1, 0.5); });
    const before = await state();

    // the colour of a robot where worldToCanvas puts it (behind its centre), and a click there
    const colourAt = (r, k) => page.evaluate(([r, k]) => {
      const p = window.afrpReplay.worldToCanvas(r.x - k * Math.cos(r.heading), r.y - k * Math.sin(r.heading));
      return Array.from(document.getElementById('world').getContext('2d').getImageData(Math.round(p[0]), Math.round(p[1]), 1, 1).data.slice(0, 3));
    }, [r, k]);
    const clickSelects = async (s, i) => {
      await page.evaluate(() => window.afrpReplay.selectRobot(-1));
      const r = s.robots[i], cssPx = s.css / s.width;
      const p = await page.evaluate(r => window.afrpReplay.worldToCanvas(r.x - 0.1 * Math.cos(r.heading), r.y - 0.1 * Math.sin(r.heading)), r);
      await page.mouse.click(s.inner[0] + p[0] * cssPx, s.inner[1] + p[1] * cssPx);
      return page.evaluate(() => window.afrpReplay.selected());
    };

    for (const [z, ratio] of [[2, 2], [1.5, 1.5], [0.5, 1], [1, 1]]) {
      await zoom(z);
      const s = await state(), what = 'at a zoom of ' + z * 100 + '% (devicePixelRatio ' + s.dpr + ')';
      const want = Math.round(640 * ratio);
      check(s.width === want && s.height === want, what + ' the canvas has ' + want + ' by ' + want + ' pixels (' + s.width + ' by ' + s.height + ')');
      // (or scaled to fit a window narrower than it: 600 CSS pixels at 200%)
      check(s.css === s.cssHeight && (s.css === 640 || (s.css < 640 && s.inner[0] + s.css <= s.page)),
            what + ' and is shown 640 by 640 CSS pixels, or scaled to fit the window (' + s.css + ' by ' + s.cssHeight +
            ' in a window of ' + s.page + ')');
      check(Math.abs(s.scale - before.scale * ratio) < 1e-9, what + ' worldToCanvas is in its pixels: ' + (before.scale * ratio) +
            ' a metre (' + s.scale + ')');
      check(s.frame === 12 && JSON.stringify(s.view) === JSON.stringify(before.view) &&
            near(s.middle, [s.width / 2, s.height / 2], 1e-6), what + ' the frame and the view are kept (' + JSON.stringify([s.frame, s.view, s.middle]) + ')');
      const a = await colourAt(s.robots[0], s.radius / 2), bB = await colourAt(s.robots[1], s.radius / 2);
      check(near(a, [30, 90, 220], 2) && near(bB, [215, 40, 40], 2), what + ' the robots are drawn where worldToCanvas puts them (' +
            JSON.stringify([a, bB]) + ')');
      check(await clickSelects(s, 1) === 1, what + ' a click on SimbotB 2 selects it');
    }
    // a resize alone (the ratio kept) keeps the canvas's pixels, and gives no canvas a width
    const spied = await spy();
    await cdp.send('Emulation.setDeviceMetricsOverride', { width: 900, height: 700, deviceScaleFactor: 1, mobile: false });
    await page.evaluate(() => new Promise(done => requestAnimationFrame(() => requestAnimationFrame(done))));
    const resized = await state();
    const spiedAfter = await spy();
    check(resized.width === 640 && resized.css === 640 && spiedAfter.widths === spied.widths,
          'a resize that keeps the ratio keeps the canvas, made afresh no canvas (' + resized.width + ', shown ' + resized.css +
          '; widths given ' + spied.widths + ' then ' + spiedAfter.widths + ')');
    check(spiedAfter.listeners === 1, 'after every change of ratio, one listener of a media query is left (' + spiedAfter.listeners + ')');
    check(errors.length === 0, 'no errors on the page' + (errors.length ? ': ' + errors.join('; ') : ''));
});
