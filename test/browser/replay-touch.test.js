// Loads an afrp replay page in headless Chromium as a phone (a touch
// screen, and the page laid out as on a phone) and checks the fingers'
// gestures:
//   node replay-touch.test.js PAGE.html
// The page must show SimbotA 1 and SimbotB 2, at least 3 m apart, in a
// world of at least 10 m. A pinch zooms by the change of the fingers'
// distance and keeps the world point under their midpoint under it, also
// as the midpoint moves; lifting one finger goes on as a drag, without a
// jump; a one-finger drag moves the view and selects nothing; a tap
// selects a robot; a pinch or a drag unticks "follow"; a touchpad's pinch
// (the wheel with the control key) zooms about the pointer; on a phone's
// narrow screen the canvas is shown scaled to fit, a tap still selecting
// the robot under it; and a vertical swipe on the canvas scrolls the page
// in the whole world's view (where the view cannot move), and moves the
// view, not the page, when zoomed. The touches are sent as Chromium's own (CDP
// Input.dispatchTouchEvent), which the page receives as pointer events.
// Chromium: $CHROMIUM, else /usr/bin/chromium. Exits 0 when every check
// passes, 1 with the failures listed otherwise.
'use strict';
const { run, check, near } = require('./harness');

run('node replay-touch.test.js PAGE.html', async (page, errors, open) => {
    await open();
    const cdp = await page.context().newCDPSession(page);
    // fingers: [[x, y], ...] in page pixels, the k-th with id k unless a third element names it;
    // 'touchEnd' lifts the fingers it lists (all, when it lists none)
    const touch = (type, fingers) => cdp.send('Input.dispatchTouchEvent',
      { type, touchPoints: fingers.map((f, k) => ({ x: f[0], y: f[1], id: f.length > 2 ? f[2] : k })) });
    const nextFrame = () => page.evaluate(() => new Promise(done => requestAnimationFrame(() => done())));
    const view = () => page.evaluate(() => window.afrpReplay.view());
    // the canvas's first pixel on the page, inside its border, and its pixels a page pixel
    const layout = () => page.evaluate(() => {
      const c = document.getElementById('world'), r = c.getBoundingClientRect();
      return { inner: [r.left + c.clientLeft, r.top + c.clientTop], ratio: c.width / c.clientWidth,
               shown: r.width, width: c.width, page: document.documentElement.clientWidth };
    });
    const toCanvas = (l, p) => [(p[0] - l.inner[0]) * l.ratio, (p[1] - l.inner[1]) * l.ratio];
    const worldUnder = (l, p) => page.evaluate(q => window.afrpReplay.canvasToWorld(q[0], q[1]), toCanvas(l, p));
    // the page point of a world point
    const pageOf = async (l, x, y) => {
      const c = await page.evaluate(([x, y]) => window.afrpReplay.worldToCanvas(x, y), [x, y]);
      return [l.inner[0] + c[0] / l.ratio, l.inner[1] + c[1] / l.ratio];
    };
    const mid = (a, b) => [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];

    const touchAction = () => page.evaluate(() => getComputedStyle(document.getElementById('world')).touchAction);
    check(await touchAction() === 'pan-y', 'the whole world\'s view leaves vertical swipes to the page (touch-action: pan-y)');
    const l = await layout();
    const info = await page.evaluate(() => ({ robots: window.afrpReplay.frameData().robots,
                                                 scale: window.afrpReplay.worldToCanvas(1, 0)[0] - window.afrpReplay.worldToCanvas(0, 0)[0] }));

    // a pinch, its midpoint still: the zoom is the fingers' distance over their distance at the start
    const m = [Math.round(l.inner[0] + 200), Math.round(l.inner[1] + 260)];
    const worldAtM = await worldUnder(l, m);
    await touch('touchStart', [[m[0] - 40, m[1]], [m[0] + 40, m[1]]]);
    for (const d of [55, 70, 85, 100]) await touch('touchMove', [[m[0] - d, m[1]], [m[0] + d, m[1]]]);
    await nextFrame();
    const pinched = await view();
    check(Math.abs(pinched.zoom - 2.5) < 1e-9, 'spreading two fingers from 80 to 200 pixels apart zooms 2.5 times (' + pinched.zoom + ')');
    check(near(await worldUnder(l, m), worldAtM, 1e-9), 'about the world point under their midpoint');
    check(await touchAction() === 'none', 'a zoomed view takes every touch itself (touch-action: none)');
    // the midpoint moves, the distance stays: the view moves with it, the zoom stays
    for (const k of [1, 2, 3]) await touch('touchMove', [[m[0] - 100 + 10 * k, m[1] - 7 * k], [m[0] + 100 + 10 * k, m[1] - 7 * k]]);
    await nextFrame();
    const m2 = [m[0] + 30, m[1] - 21];
    check((await view()).zoom === pinched.zoom && near(await worldUnder(l, m2), worldAtM, 1e-9),
          'moving both fingers moves the view with them, the same world point under their midpoint');
    // lifting the second finger, then moving the first: a drag from where the view is, no jump
    await touch('touchEnd', [[m2[0] + 100, m2[1], 1]]);
    await nextFrame();
    const lifted = await view();
    await touch('touchMove', [[m2[0] - 150, m2[1] + 20]]);
    await nextFrame();
    const s = info.scale * lifted.zoom, afterLift = await view();
    check(lifted.zoom === pinched.zoom && afterLift.zoom === lifted.zoom && Math.abs(afterLift.cx - (lifted.cx + 50 / s)) < 1e-9 &&
          Math.abs(afterLift.cy - (lifted.cy + 20 / s)) < 1e-9,
          'lifting one finger of a pinch goes on as a drag by the other finger, without a jump');
    await touch('touchEnd', []);
    await nextFrame();
    check(await page.evaluate(() => window.afrpReplay.selected()) === -1, 'a pinch selects nothing');

    // a tap on SimbotB 2 selects it
    await page.evaluate(() => window.afrpReplay.setView(1.5, 0, 0));
    const rB = info.robots[1];
    const atB = await pageOf(l, rB.x, rB.y);
    await touch('touchStart', [atB]);
    await touch('touchEnd', []);
    await page.waitForFunction(() => window.afrpReplay.selected() === 1, null, { timeout: 3000 }).catch(() => {});
    check(await page.evaluate(() => window.afrpReplay.selected()) === 1, 'a tap on SimbotB 2 selects it');
    // a one-finger drag moves the view, keeps the selection, and unticks follow
    await page.check('#follow');
    await page.evaluate(() => window.afrpReplay.setView(2, 0, 0));
    const before = await view(), s2 = info.scale * before.zoom;
    await touch('touchStart', [[m[0], m[1]]]);
    for (const k of [1, 2, 3, 4]) await touch('touchMove', [[m[0] + 15 * k, m[1] + 10 * k]]);
    await touch('touchEnd', []);
    await nextFrame();
    const dragged = await view();
    check(Math.abs(dragged.cx - (before.cx - 60 / s2)) < 1e-9 && Math.abs(dragged.cy - (before.cy + 40 / s2)) < 1e-9 &&
          dragged.zoom === before.zoom, 'a one-finger drag moves the view with the finger');
    check(await page.evaluate(() => window.afrpReplay.selected()) === 1 && !(await page.isChecked('#follow')),
          'and keeps the selection, unticking follow');
    await page.check('#follow');
    await touch('touchStart', [[m[0] - 30, m[1]], [m[0] + 30, m[1]]]);
    await touch('touchMove', [[m[0] - 45, m[1]], [m[0] + 45, m[1]]]);
    await touch('touchEnd', []);
    check(!(await page.isChecked('#follow')), 'a pinch unticks follow too');
    check(await page.evaluate(() => window.scrollX === 0 && window.scrollY === 0), 'the page itself did not scroll');

    // a touchpad's pinch: the wheel with the control key, in larger steps than the wheel alone
    await page.evaluate(() => window.afrpReplay.setView(1, 0, 0));
    await page.mouse.move(m[0], m[1]);
    await page.keyboard.down('Control');
    await page.mouse.wheel(0, -30);
    await page.keyboard.up('Control');
    await page.waitForFunction(() => window.afrpReplay.view().zoom > 1, null, { timeout: 3000 }).catch(() => {});
    check(Math.abs((await view()).zoom - Math.exp(0.3)) < 1e-9 && near(await worldUnder(l, m), worldAtM, 1e-9),
          'a touchpad\'s pinch (the wheel with the control key, -30) zooms exp(0.3) times about the pointer (' + (await view()).zoom + ')');

    // a phone's narrow screen: the canvas is scaled to fit, and a tap still finds the robot under it
    await page.setViewportSize({ width: 360, height: 740 });
    await page.evaluate(() => { window.afrpReplay.selectRobot(-1); window.afrpReplay.setView(1, 0, 0); });
    const narrow = await layout();
    check(narrow.shown <= narrow.page && narrow.ratio > 1.2,
          'on a 360-pixel screen the canvas is shown ' + Math.round(narrow.shown) + ' pixels wide, within the page (' + narrow.page + ')');
    const rA = info.robots[0];
    const atA = await pageOf(narrow, rA.x, rA.y);
    await touch('touchStart', [atA]);
    await touch('touchEnd', []);
    await page.waitForFunction(() => window.afrpReplay.selected() === 0, null, { timeout: 3000 }).catch(() => {});
    check(await page.evaluate(() => window.afrpReplay.selected()) === 0, 'a tap on SimbotA 1 in the scaled canvas selects it');
    // a vertical swipe on the canvas: the page scrolls in the whole world's view, the view moves when zoomed
    await page.setViewportSize({ width: 360, height: 480 });
    const swipe = async () => {
      const lay = await layout(), x = lay.inner[0] + 100, y = lay.inner[1] + 250;
      await touch('touchStart', [[x, y]]);
      for (const k of [1, 2, 3, 4, 5, 6]) await touch('touchMove', [[x, y - 25 * k]]);
      await touch('touchEnd', []);
      await page.waitForTimeout(300);
      await nextFrame();
    };
    const fitView = await view();
    await swipe();
    const scrolled = await page.evaluate(() => window.scrollY);
    check(scrolled > 50 && JSON.stringify(await view()) === JSON.stringify(fitView),
          'in the whole world\'s view a vertical swipe on the canvas scrolls the page (' + scrolled + ' pixels), the view stays');
    await page.evaluate(() => { window.scrollTo(0, 0); window.afrpReplay.setView(2, 0, 0); });
    const zoomedView = await view();
    await swipe();
    check(await page.evaluate(() => window.scrollY) === 0 && (await view()).cy < zoomedView.cy,
          'in a zoomed view the same swipe moves the view, not the page');
    check(errors.length === 0, 'no errors on the page' + (errors.length ? ': ' + errors.join('; ') : ''));
}, { hasTouch: true, isMobile: true });
