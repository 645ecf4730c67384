// Loads an afrp replay page in headless Chromium as a phone (a touch
// screen, and the page laid out as on a phone) and checks the fingers'
// gestures:
//   node replay-touch.test.js PAGE.html
// The page must show SimbotA 1 and SimbotB 2, at least 3 m apart, in a
// world of at least 10 m. A pinch zooms by the change of the fingers'
// distance and keeps the world point under their midpoint under it, also
// as the midpoint moves; lifting one finger goes on as a drag, without a
// jump; a one-finger drag moves the view and selects nothing; a tap
// selects a robot once (the click after it passed over), also when the
// finger moves a little, also up to 16 CSS pixels off its disc (a mouse's
// click there selects nothing; a pen reaches 8), and also right after a
// flick (a later mouse click still selecting); a pinch or a drag that
// moves the view unticks "follow"; a touchpad's pinch (the wheel with the
// control key, in small steps) zooms about the pointer, and a wheel
// counting lines zooms as one counting pixels; on a phone's narrow screen
// the canvas is shown scaled to fit, a tap still selecting the robot under
// it, and one 12 CSS pixels off its disc; and a vertical swipe on the
// canvas scrolls the page in the whole world's view (where the view cannot
// move, and follow stays ticked), and moves the view, not the page, when
// zoomed. The touches are sent as Chromium's own (CDP
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
    const selected = () => page.evaluate(() => window.afrpReplay.selected());
    // a tap on robot k of the frame, the finger moving 3 pixels on the way (as a finger does):
    // whether it selected the robot
    const tapSelects = async (lay, k) => {
      const r = info.robots[k], at = await pageOf(lay, r.x, r.y);
      await touch('touchStart', [at]);
      await touch('touchMove', [[at[0] + 2, at[1] + 1]]);
      await touch('touchEnd', []);
      await page.waitForFunction(k => window.afrpReplay.selected() === k, k, { timeout: 3000 }).catch(() => {});
      return (await selected()) === k;
    };
    // a finger's drag from a point by steps of (dx, dy), held still before it is lifted: a
    // finger lifted while moving flings on (a page scrolled by it would go on scrolling, and
    // Chromium takes the next tap for the one that stops the fling; the flick check below
    // lifts the finger moving on purpose)
    const drag = async (from, dx, dy, steps) => {
      await touch('touchStart', [from]);
      for (let k = 1; k <= steps; k++) await touch('touchMove', [[from[0] + dx * k, from[1] + dy * k]]);
      for (let k = 0; k < 4; k++) { await page.waitForTimeout(50); await touch('touchMove', [[from[0] + dx * steps, from[1] + dy * steps]]); }
      await touch('touchEnd', []);
      await nextFrame();
    };
    // a swipe up the canvas, and the page's scrolling come to rest
    const swipe = async () => {
      const lay = await layout();
      await drag([lay.inner[0] + 100, lay.inner[1] + 250], 0, -25, 6);
      // (at rest: the same scroll position over three animation frames after 150 ms, twice running)
      const settledAt = () => page.evaluate(() => new Promise(done => {
        const y0 = window.scrollY;
        setTimeout(() => requestAnimationFrame(() => requestAnimationFrame(() => requestAnimationFrame(() =>
          done(window.scrollY === y0 ? y0 : null)))), 150);
      }));
      for (let still = 0, k = 0; still < 2 && k < 200; k++) still = (await settledAt()) === null ? 0 : still + 1;
      await nextFrame();
    };

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

    // a one-finger drag that starts on SimbotB 2 moves the view and selects nothing
    await page.evaluate(() => window.afrpReplay.setView(2, 0, 0));
    const before = await view(), s2 = info.scale * before.zoom, rB = info.robots[1];
    await drag(await pageOf(l, rB.x, rB.y), 15, 10, 4);
    const dragged = await view();
    check(Math.abs(dragged.cx - (before.cx - 60 / s2)) < 1e-9 && Math.abs(dragged.cy - (before.cy + 40 / s2)) < 1e-9 &&
          dragged.zoom === before.zoom, 'a one-finger drag moves the view with the finger');
    check(await selected() === -1, 'a drag that starts on SimbotB 2 does not select it');
    // a tap on SimbotB 2 selects it; a drag then keeps the selection and unticks follow
    await page.evaluate(() => window.afrpReplay.setView(1.5, 0, 0));
    check(await tapSelects(l, 1), 'a tap on SimbotB 2 selects it');
    // the page point gap page pixels to the right of robot k's disc, in the view at a zoom
    const offDisc = async (gap, lay = l, k = 1, zoom = 1.5) => {
      const radius = await page.evaluate(k => window.afrpReplay.header.robots[k].radius, k);
      const r = info.robots[k], c = await pageOf(lay, r.x, r.y);
      return [c[0] + radius * info.scale * zoom / lay.ratio + gap, c[1]];
    };
    // a finger's tap, still, at a page point: what it selected
    const fingerTap = async (at) => {
      await page.evaluate(() => window.afrpReplay.selectRobot(-1));
      await touch('touchStart', [at]);
      await touch('touchEnd', []);
      await page.waitForFunction(() => window.afrpReplay.selected() !== -1, null, { timeout: 1500 }).catch(() => {});
      return selected();
    };
    // a finger covers more than it points at: a tap up to 16 CSS pixels off SimbotB 2's disc
    // selects it, where a mouse's click selects nothing (3 canvas pixels)
    const counted = await page.evaluate(() => window.afrpReplay.selections());
    // (the clicks the page is sent, counted before its own handlers see them)
    await page.evaluate(() => { window.clicksSeen = 0; document.addEventListener('click', () => { window.clicksSeen++; }, true); });
    check(await fingerTap(await offDisc(12)) === 1, 'a tap 12 pixels off SimbotB 2\'s disc selects it');
    // (the click that follows the tap, waited for, up to 30 s)
    await page.waitForFunction(() => window.clicksSeen > 0, null, { timeout: 30000 }).catch(() => {});
    await nextFrame();
    check(await page.evaluate(() => window.afrpReplay.selections()) === counted + 1,
          'once: the click that follows the tap is passed over');
    check(await fingerTap(await offDisc(22)) === -1, 'a tap 22 pixels off it selects nothing');
    await page.evaluate(() => window.afrpReplay.selectRobot(-1));
    const off12 = await offDisc(12);
    await page.mouse.click(off12[0], off12[1]);
    await nextFrame();
    check(await selected() === -1, 'a mouse\'s click 12 pixels off it selects nothing');
    // a pen reaches 8 CSS pixels: 6 off the disc selects, 12 off does not
    const penClick = async (at) => {
      await page.evaluate(() => window.afrpReplay.selectRobot(-1));
      for (const type of ['mousePressed', 'mouseReleased'])
        await cdp.send('Input.dispatchMouseEvent', { type, x: at[0], y: at[1], button: 'left', clickCount: 1, pointerType: 'pen' });
      await page.waitForFunction(() => window.afrpReplay.selected() !== -1, null, { timeout: 1500 }).catch(() => {});
      return selected();
    };
    check(await penClick(await offDisc(6)) === 1 && await penClick(await offDisc(12)) === -1,
          'a pen\'s tap selects SimbotB 2 from 6 pixels off its disc, not from 12');
    check(await tapSelects(l, 1), 'and a tap on it selects it again');
    // a quick drag, lifted while the finger still moves (a flick), then at once a tap on a
    // robot: the tap selects it (Chromium fires no click for the tap right after a flick)
    await page.evaluate(() => { window.afrpReplay.selectRobot(-1); window.afrpReplay.setView(2, 0, 0); });
    await touch('touchStart', [m]);
    for (let k = 1; k <= 5; k++) await touch('touchMove', [[m[0] + 12 * k, m[1] + 4 * k]]);
    await touch('touchEnd', []);
    await nextFrame();
    const afterFlick = await pageOf(l, rB.x, rB.y);
    check(await fingerTap(afterFlick) === 1, 'a tap right after a flick selects the robot under it');
    // and the mouse's next click is not passed over (the tap's click never came)
    const rA = info.robots[0], atA = await pageOf(l, rA.x, rA.y);
    await page.mouse.click(atA[0], atA[1]);
    await page.waitForFunction(() => window.afrpReplay.selected() === 0, null, { timeout: 1500 }).catch(() => {});
    check(await selected() === 0, 'a mouse click on SimbotA 1 after that selects it');
    await page.evaluate(() => window.afrpReplay.selectRobot(1));
    await page.check('#follow');
    await page.evaluate(() => window.afrpReplay.setView(2, 0, 0));
    await drag(m, 15, 10, 4);
    check(await selected() === 1 && !(await page.isChecked('#follow')), 'a drag keeps the selection, and unticks follow');
    await page.check('#follow');
    await touch('touchStart', [[m[0] - 30, m[1]], [m[0] + 30, m[1]]]);
    await touch('touchMove', [[m[0] - 45, m[1]], [m[0] + 45, m[1]]]);
    await touch('touchEnd', []);
    check(!(await page.isChecked('#follow')), 'a pinch unticks follow too');
    check(await page.evaluate(() => window.scrollX === 0 && window.scrollY === 0), 'the page itself did not scroll');

    // the wheel's kinds: a touchpad's pinch (the control key, small steps) zooms more a pixel
    // than a wheel, also a mouse wheel with the control key held; a wheel counting lines, 40
    // pixels a line
    const wheelZoom = async (init) => {
      await page.evaluate(() => window.afrpReplay.setView(1, 0, 0));
      await page.evaluate(([init, x, y]) => document.getElementById('world').dispatchEvent(
        new WheelEvent('wheel', Object.assign({ clientX: x, clientY: y, cancelable: true, bubbles: true }, init))), [init, m[0], m[1]]);
      return { zoom: (await view()).zoom, under: await worldUnder(l, m) };
    };
    const pinchpad = await wheelZoom({ deltaY: -30, ctrlKey: true });
    check(Math.abs(pinchpad.zoom - Math.exp(0.3)) < 1e-9 && near(pinchpad.under, worldAtM, 1e-9),
          'a touchpad\'s pinch (the wheel with the control key, -30) zooms exp(0.3) times about the pointer (' + pinchpad.zoom + ')');
    const ctrlWheel = await wheelZoom({ deltaY: -100, ctrlKey: true });
    check(Math.abs(ctrlWheel.zoom - Math.exp(0.2)) < 1e-9,
          'a mouse wheel\'s step (-100) with the control key zooms as without it, exp(0.2) times (' + ctrlWheel.zoom + ')');
    const lines = await wheelZoom({ deltaY: -3, deltaMode: 1 });
    check(Math.abs(lines.zoom - Math.exp(0.24)) < 1e-9, 'a wheel counting 3 lines zooms as 120 pixels, exp(0.24) times (' + lines.zoom + ')');

    // a phone's narrow screen: the canvas is scaled to fit, and a tap still finds the robot under it
    await page.setViewportSize({ width: 360, height: 740 });
    await page.evaluate(() => { window.afrpReplay.selectRobot(-1); window.afrpReplay.setView(1, 0, 0); });
    const narrow = await layout();
    check(narrow.shown <= narrow.page && narrow.ratio > 1.2,
          'on a 360-pixel screen the canvas is shown ' + Math.round(narrow.shown) + ' pixels wide, within the page (' + narrow.page + ')');
    check(await tapSelects(narrow, 0), 'a tap on SimbotA 1 in the scaled canvas selects it (the finger moving 3 pixels)');
    check(12 * narrow.ratio > 16 && await fingerTap(await offDisc(12, narrow, 0, 1)) === 0,
          'and a tap 12 page pixels off its disc (' + (12 * narrow.ratio).toFixed(1) + ' canvas pixels) selects it too');
    // a vertical swipe on the canvas: the page scrolls in the whole world's view (follow stays
    // ticked, the selection kept), the view moves when zoomed
    await page.setViewportSize({ width: 360, height: 480 });
    await page.check('#follow');
    const fitView = await view();
    await swipe();
    const scrolled = await page.evaluate(() => window.scrollY);
    check(scrolled > 50 && JSON.stringify(await view()) === JSON.stringify(fitView),
          'in the whole world\'s view a vertical swipe on the canvas scrolls the page (' + scrolled + ' pixels), the view stays');
    check(await page.isChecked('#follow') && await selected() === 0, 'and leaves follow ticked and the selection');
    await page.evaluate(() => { window.scrollTo(0, 0); window.afrpReplay.setView(2, 0, 0); });
    await page.waitForFunction(() => window.scrollY === 0);
    const zoomedView = await view();
    await swipe();
    check(await page.evaluate(() => window.scrollY) === 0 && (await view()).cy < zoomedView.cy,
          'in a zoomed view the same swipe moves the view, not the page');
    check(errors.length === 0, 'no errors on the page' + (errors.length ? ': ' + errors.join('; ') : ''));
}, { hasTouch: true, isMobile: true });
