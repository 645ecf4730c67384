// Loads an afrp replay page in headless Chromium and checks it works:
//   node replay.test.js PAGE.html [SCREENSHOT.png]
// The page must be that of the test fixture (test/AFrobRobotSim/LogFixture.hs):
// SimbotA 1 and SimbotB 2, and SimbotA 1 prints a hostile message at 0.5 s.
// Chromium: $CHROMIUM, else /usr/bin/chromium (Debian: apt-get install chromium).
// Exits 0 when every check passes, 1 with the failures listed otherwise.
'use strict';
const path = require('path');
const { run, check, near } = require('./harness');

const shotPath = process.argv[3] || path.join(__dirname, '..', '..', 'docs', 'images', 'replay.png');
const background = [240, 240, 230];

run('node replay.test.js PAGE.html [SCREENSHOT.png]', async (page, errors, open) => {
    const requests = [];
    page.on('request', r => { if (!r.url().startsWith('file:') && !r.url().startsWith('data:')) requests.push(r.url()); });
    await open();

    // the pixel of the canvas under a world point, shifted (dx, dy) canvas pixels
    const pixelAt = (x, y, dx, dy) => page.evaluate(([x, y, dx, dy]) => {
      const c = document.getElementById('world');
      const p = window.afrpReplay.worldToCanvas(x, y);
      return Array.from(c.getContext('2d').getImageData(Math.round(p[0] + dx), Math.round(p[1] + dy), 1, 1).data.slice(0, 3));
    }, [x, y, dx, dy]);
    // a point of a robot's body behind its centre (the heading line runs forward from it)
    const bodyPixel = async (r, radiusPx) => pixelAt(r.x, r.y, -0.5 * radiusPx * Math.cos(r.heading), 0.5 * radiusPx * Math.sin(r.heading));
    const info = await page.evaluate(() => ({
      n: window.afrpReplay.frameCount(), robots: window.afrpReplay.header.robots,
      first: window.afrpReplay.frameData(0), last: window.afrpReplay.frameData(window.afrpReplay.frameCount() - 1),
      bounds: window.afrpReplay.header.bounds, width: document.getElementById('world').width,
      scale: window.afrpReplay.worldToCanvas(1, 0)[0] - window.afrpReplay.worldToCanvas(0, 0)[0] }));
    check(info.n > 10, 'the page has the log\'s frames (' + info.n + ')');
    check(info.robots.length === 2 && info.robots[0].type === 'SimbotA', 'the header lists the fixture\'s robots');
    const radiusPx = info.robots[0].radius * info.scale;
    const blue = [30, 90, 220], red = [215, 40, 40];

    // time 0: each robot drawn where the log puts it
    check(near(await bodyPixel(info.first.robots[0], radiusPx), blue, 2), 'at time 0 SimbotA 1 is drawn at its logged position');
    check(near(await bodyPixel(info.first.robots[1], radiusPx), red, 2), 'at time 0 SimbotB 2 is drawn at its logged position');
    check(near(await pixelAt(-4.5, -4.5, 0, 0), background, 0), 'empty floor is the background colour');

    // the toggles: SimbotA 1's front ray crosses (0, 0) at time 0 (its reading is 3 m from x = -2)
    // (a 1-pixel line is anti-aliased over two rows of pixels: either is greenish)
    const greenish = c => c[1] > c[0] + 40 && c[1] > c[2] + 40;
    const rayRows = async () => [await pixelAt(0, 0, 0, -1), await pixelAt(0, 0, 0, 0)];
    check((await rayRows()).some(greenish), 'range rays are drawn (front ray of SimbotA 1 at (0, 0))');
    // a reading is from the robot's edge: the front ray of 3 m from x = -2 ends at x = 1.25, not 1
    const rayAt = async x => [await pixelAt(x, 0, 0, -1), await pixelAt(x, 0, 0, 0)];
    check((await rayAt(1.15)).some(greenish), 'a range ray runs from the robot\'s edge (drawn at x = 1.15)');
    check((await rayAt(1.4)).every(c => !greenish(c)), 'a range ray ends at its reading (none at x = 1.4)');
    await page.uncheck('#rays');
    check((await rayRows()).every(c => near(c, background, 0)), 'unticking "range rays" hides them');
    await page.check('#rays');
    await page.focus('#speed');   // (as choosing with the mouse leaves it)
    await page.selectOption('#speed', '4');
    check(await page.evaluate(() => document.getElementById('speed').value) === '4', 'the speed can be set');
    // and the keys work straight after (the list kept the focus, and the page left the keys to it)
    const beforeKey = await page.evaluate(() => window.afrpReplay.frame());
    await page.keyboard.press('ArrowRight');
    const afterKey = await page.evaluate(() => window.afrpReplay.frame());
    check(afterKey === beforeKey + 1, 'after choosing a speed, ArrowRight steps a frame (' + beforeKey + ' -> ' + afterKey + ')');
    await page.keyboard.press('ArrowLeft');

    // drag the slider to the end (keyboard End on the focused range input: a real input event)
    await page.focus('#slider');
    await page.keyboard.press('End');
    const frameAtEnd = await page.evaluate(() => window.afrpReplay.frame());
    check(frameAtEnd === info.n - 1, 'the slider at its end shows the last frame (' + frameAtEnd + ')');
    check(near(await bodyPixel(info.last.robots[1], radiusPx), red, 2), 'at the end SimbotB 2 is drawn at its final logged position');
    check(!near(await bodyPixel(info.first.robots[1], radiusPx), red, 30), 'and no longer at its first position');
    check(near(await bodyPixel(info.last.robots[0], radiusPx), blue, 2), 'at the end SimbotA 1 is drawn at its final logged position');

    // trails: SimbotB 2 drove from x = 2 to x = 1 along y = 1.5, so at the end its path is drawn at
    // (1.5, 1.5) (a 1-pixel line, over two rows; the range rays off: its back ray runs along that path)
    await page.uncheck('#rays');
    const reddish = c => c[0] > c[1] + 20 && c[0] > c[2] + 20;
    const trailRows = async () => [await pixelAt(1.5, 1.5, 0, -1), await pixelAt(1.5, 1.5, 0, 0), await pixelAt(1.5, 1.5, 0, 1)];
    const trailsAtEnd = await trailRows();
    check(trailsAtEnd.some(reddish), 'trails are drawn (SimbotB 2\'s path behind it: ' + JSON.stringify(trailsAtEnd) + ')');
    await page.uncheck('#trails');
    check((await trailRows()).every(c => near(c, background, 0)), 'unticking "trails" hides them');
    await page.check('#trails');
    check(JSON.stringify(await trailRows()) === JSON.stringify(trailsAtEnd), 'ticking it again shows the same trails');
    // the trails of the frames played one by one (each frame adds its stretch) and of a jump to the
    // end (drawn whole) are the same, but for the anti-aliasing where the stretches meet
    const stepped = await page.evaluate(() => {
      const R = window.afrpReplay, k = R.frameCount(), c = document.getElementById('world'), g = c.getContext('2d');
      const grab = () => g.getImageData(0, 0, c.width, c.height).data;
      R.setFrame(0);
      for (let i = 1; i < k; i++) R.setFrame(i);
      const a = grab();
      R.setFrame(0);
      R.setFrame(k - 1);
      const b = grab();
      let differ = 0, trail = 0;
      for (let i = 0; i < a.length; i += 4) {
        if (a[i] !== b[i] || a[i + 1] !== b[i + 1] || a[i + 2] !== b[i + 2]) differ++;
        if (b[i] > b[i + 1] + 20 && b[i] > b[i + 2] + 20) trail++;
      }
      return { differ: differ, reddish: trail };
    });
    check(stepped.differ <= 60 && stepped.reddish > 100, 'frames played one by one draw the trails a jump to the end draws (' +
          stepped.differ + ' pixels differ, ' + stepped.reddish + ' reddish)');
    // going back starts from a copy of the trails kept at an earlier frame (every 25th here): the same
    // pixels as the trails drawn afresh (another view and back, which drops the copies)
    const back = await page.evaluate(() => {
      const R = window.afrpReplay, k = R.frameCount(), b = R.header.bounds, c = document.getElementById('world'), g = c.getContext('2d');
      const grab = () => g.getImageData(0, 0, c.width, c.height).data;
      const differ = (x, y) => { let n = 0; for (let i = 0; i < x.length; i++) if (x[i] !== y[i]) n++; return n; };
      const afresh = () => { R.setView(2, b.x, b.y); R.setView(1, b.x, b.y); return grab(); };
      const out = [];
      [[k - 1, 27], [35, 20], [k - 1, 25], [k - 1, 49]].forEach(p => {
        R.setFrame(p[0]); R.setFrame(p[1]);
        const kept = grab();
        out.push(differ(kept, afresh()));
      });
      return { differ: out, k: k };
    });
    check(back.k > 50 && back.differ.every(n => n === 0),
          'going back draws the trails drawn afresh (values differing at frames 27, 20, 25, 49: ' + back.differ.join(', ') + ')');
    await page.evaluate(() => window.afrpReplay.setFrame(0));
    const atStart = await trailRows();
    check(atStart.every(c => near(c, background, 0)), 'back at the start, the trails are gone (' + JSON.stringify(atStart) + ')');
    await page.evaluate(() => window.afrpReplay.setFrame(window.afrpReplay.frameCount() - 1));
    await page.check('#rays');

    // click a robot: its readings appear
    const box = await page.locator('#world').boundingBox();
    const p = await page.evaluate(r => window.afrpReplay.worldToCanvas(r.x, r.y), info.last.robots[0]);
    await page.mouse.click(box.x + p[0] - 0.5 * radiusPx * Math.cos(info.last.robots[0].heading), box.y + p[1]);
    const text = await page.locator('#info').textContent();
    check(text.includes('SimbotA 1'), 'clicking SimbotA 1 shows its panel');
    check(/wheels\s+left -?\d/.test(text) && /range\s+front \d/.test(text) && text.includes('battery'),
          'the panel shows its wheel speeds, range readings and battery');
    check(text.includes('</script><img src=x onerror="window.__pwned=1">'), 'its hostile message is shown as text');
    // (the page's own script, and its log's data elements: #afrp-log and,
    // for a long log, #afrp-log-2, #afrp-log-3, ...)
    const pwned = await page.evaluate(() => ({ flag: window.__pwned, imgs: document.querySelectorAll('img').length,
                                               scripts: document.querySelectorAll('script').length,
                                               data: document.querySelectorAll('script[id^="afrp-log"]').length }));
    check(pwned.flag === undefined && pwned.imgs === 0 && pwned.data >= 1 && pwned.scripts === pwned.data + 1,
          'the hostile message ran no script and made no element');

    // zoom and move: the wheel zooms about the point under it, the robots grow with the view, the
    // trails are drawn in it, a drag moves it without selecting, 0 / + / Fit and the limits
    await page.uncheck('#rays');
    const rB = info.last.robots[1];
    const view = () => page.evaluate(() => window.afrpReplay.view());
    const canvasOf = r => page.evaluate(r => window.afrpReplay.worldToCanvas(r.x, r.y), r);
    const pixel = p => page.evaluate(p => Array.from(document.getElementById('world').getContext('2d')
                                                    .getImageData(Math.round(p[0]), Math.round(p[1]), 1, 1).data.slice(0, 3)), p);
    // (a point beside SimbotB 2, k pixels from its centre across its heading)
    const beside = async k => { const c = await canvasOf(rB); return pixel([c[0] + k * Math.sin(rB.heading), c[1] + k * Math.cos(rB.heading)]); };
    const nextFrame = () => page.evaluate(() => new Promise(done => requestAnimationFrame(() => done())));
    // (the canvas's first pixel on the page, inside its border)
    const inner = await page.evaluate(() => { const c = document.getElementById('world'), r = c.getBoundingClientRect();
                                              return [r.left + c.clientLeft, r.top + c.clientTop]; });
    const fitB = await canvasOf(rB);
    const drawnAtFit = await page.evaluate(() => window.afrpReplay.drawn());
    check(drawnAtFit.robots === 2 && drawnAtFit.labels === 2, 'the whole world in view draws both robots and their ids (' + JSON.stringify(drawnAtFit) + ')');
    check(!near(await beside(1.4 * radiusPx), red, 60), 'in the whole world\'s view, 1.4 radii beside SimbotB 2 is not its body');
    // (a whole page pixel near SimbotB 2: the mouse's events are in whole pixels)
    const cursor = (await page.evaluate(r => window.afrpReplay.worldToCanvas(r.x + 0.3, r.y + 0.2), rB))
                     .map((v, k) => Math.round(inner[k] + v) - inner[k]);
    const under = () => page.evaluate(p => window.afrpReplay.canvasToWorld(p[0], p[1]), cursor);
    const underBefore = await under();
    await page.mouse.move(inner[0] + cursor[0], inner[1] + cursor[1]);
    await page.mouse.wheel(0, -300);
    await page.waitForFunction(() => window.afrpReplay.view().zoom > 1);
    await nextFrame();
    const zoomed = await view();
    check(Math.abs(zoomed.zoom - Math.exp(0.6)) < 1e-9, 'the wheel zooms in (' + zoomed.zoom + ')');
    check(near(await under(), underBefore, 1e-9), 'about the world point under the mouse');
    check(near(await beside(0.5 * radiusPx * zoomed.zoom), red, 2) && near(await beside(1.4 * radiusPx), red, 2),
          'SimbotB 2 is drawn where the log puts it, its radius grown with the zoom');
    check((await trailRows()).some(reddish), 'the trails are drawn in the zoomed view');
    await page.mouse.move(inner[0] + cursor[0], inner[1] + cursor[1]);
    await page.mouse.down();
    await page.mouse.move(inner[0] + cursor[0] - 60, inner[1] + cursor[1] + 40, { steps: 6 });
    await page.mouse.up();
    await nextFrame();
    const dragged = await view(), s = info.scale * zoomed.zoom;
    check(Math.abs(dragged.cx - (zoomed.cx + 60 / s)) < 1e-9 && Math.abs(dragged.cy - (zoomed.cy + 40 / s)) < 1e-9 &&
          dragged.zoom === zoomed.zoom, 'a drag moves the view with the mouse');
    check(await page.evaluate(() => window.afrpReplay.selected()) === 0, 'and selects nothing');
    // a drag released off the canvas ends there: moving the mouse afterwards moves nothing
    await page.mouse.move(inner[0] + cursor[0], inner[1] + cursor[1]);
    await page.mouse.down();
    await page.mouse.move(inner[0] + info.width + 40, inner[1] + cursor[1], { steps: 4 });
    await page.mouse.up();
    await nextFrame();
    const released = await view();
    await page.mouse.move(inner[0] + cursor[0], inner[1] + cursor[1] + 30, { steps: 4 });
    await nextFrame();
    check(JSON.stringify(await view()) === JSON.stringify(released) && released.cx !== dragged.cx,
          'a drag released off the canvas ends there');
    // only the left button drags
    await page.mouse.move(inner[0] + cursor[0], inner[1] + cursor[1]);
    await page.mouse.down({ button: 'right' });
    await page.mouse.move(inner[0] + cursor[0] - 50, inner[1] + cursor[1] - 30, { steps: 4 });
    await page.mouse.up({ button: 'right' });
    await nextFrame();
    check(JSON.stringify(await view()) === JSON.stringify(released), 'the right button does not drag');
    await page.evaluate(v => window.afrpReplay.setView(v.zoom, v.cx, v.cy), dragged);
    check(near(await beside(0.5 * radiusPx * zoomed.zoom), red, 2), 'SimbotB 2 is drawn where the log puts it in the moved view');
    const bAt = await canvasOf(rB);
    await page.mouse.click(inner[0] + bAt[0] + 0.5 * radiusPx * zoomed.zoom * Math.sin(rB.heading),
                           inner[1] + bAt[1] + 0.5 * radiusPx * zoomed.zoom * Math.cos(rB.heading));
    check(await page.evaluate(() => window.afrpReplay.selected()) === 1 &&
          (await page.locator('#info').textContent()).includes('SimbotB 2'), 'clicking SimbotB 2 in the zoomed view selects it');
    await page.keyboard.press('0');
    check((await view()).zoom === 1 && near(await canvasOf(rB), fitB, 1e-9), 'key 0 shows the whole world again, as before');
    await page.keyboard.press('+');
    const plus = await view();
    check(Math.abs(plus.zoom - 1.5) < 1e-12 && Math.abs(plus.cx - info.bounds.x) < 1e-9 && Math.abs(plus.cy - info.bounds.y) < 1e-9,
          'key + zooms 1.5 times about the middle (' + JSON.stringify(plus) + ')');
    await page.click('#fit');
    check((await view()).zoom === 1, 'the Fit button shows the whole world');
    const limits = await page.evaluate(() => { const R = window.afrpReplay; R.setView(1e6, 100, -100); const a = R.view();
                                               R.setView(0.01, 3, 3); const c = R.view(); return [a, c, R.maxZoom]; });
    check(limits[0].zoom === limits[2] && Math.abs(limits[2] - 250 / info.scale) < 1e-9 &&
          Math.abs(limits[0].cx - (info.bounds.x + info.bounds.width / 2 * (1 - 1 / limits[2]))) < 1e-9 &&
          Math.abs(limits[0].cy - (info.bounds.y - info.bounds.height / 2 * (1 - 1 / limits[2]))) < 1e-9,
          'the zoom stops at 250 pixels a metre, the view within the world (' + JSON.stringify(limits[0]) + ')');
    check(limits[1].zoom === 1 && limits[1].cx === info.bounds.x && limits[1].cy === info.bounds.y,
          'and at the whole world, which it cannot leave');
    // a big page's trails while the view changes (made big here by lowering the page's bound):
    // the layer moved and scaled at once, then the paths drawn afresh once the view rests
    const bound = await page.evaluate(() => { const R = window.afrpReplay, a = R.roughAbove; R.roughAbove = 0; R.selectRobot(-1); return a; });
    await page.mouse.move(inner[0] + cursor[0], inner[1] + cursor[1]);
    await page.mouse.wheel(0, -300);
    await nextFrame();
    const rough = await page.evaluate(() => window.afrpReplay.drawn().roughTrails);
    const roughRows = await trailRows();
    check(rough && roughRows.some(reddish), 'on a big page the wheel moves the trails at once, roughly (' + JSON.stringify(roughRows) + ')');
    // (the page draws the paths afresh 250 ms after the view's last change: waited for, up to 30 s)
    await page.waitForFunction(() => !window.afrpReplay.drawn().roughTrails, null, { timeout: 30000 }).catch(() => {});
    await nextFrame();
    const settled = await page.evaluate(() => {
      const R = window.afrpReplay, k = R.frameCount(), c = document.getElementById('world'), g = c.getContext('2d');
      const grab = () => g.getImageData(0, 0, c.width, c.height).data;
      const rough = R.drawn().roughTrails, a = grab();
      R.setFrame(0); R.setFrame(k - 1);   // (the paths drawn afresh)
      const b = grab();
      let differ = 0;
      for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) differ++;
      return { rough: rough, differ: differ };
    });
    check(!settled.rough && settled.differ === 0, 'and draws them afresh once the view rests (' + settled.differ + ' values differ from the paths drawn anew)');
    await page.evaluate(b => { const R = window.afrpReplay; R.roughAbove = b; R.setView(1, R.header.bounds.x, R.header.bounds.y); }, bound);
    // follow (ticked by default; ticked again here): zoomed in on SimbotB 2 where it starts, selected, the view centres on
    // it again when it leaves the view's middle, and not while it stays there; unticked, the view stays
    const rB0 = info.first.robots[1], k = info.n;
    check(!(await page.isChecked('#follow')), 'the drag above, SimbotA 1 selected, unticked follow');
    await page.check('#follow');
    await page.evaluate(r => { const R = window.afrpReplay; R.setFrame(0); R.selectRobot(1); R.setView(R.maxZoom, r.x, r.y); }, rB0);
    await page.evaluate(k => window.afrpReplay.setFrame(k - 1), k);
    const followed = await view();
    check(followed.cx === rB.x && followed.cy === rB.y, 'following SimbotB 2, the view centres on it at the end (' + JSON.stringify(followed) + ')');
    check(near(await beside(0.5 * radiusPx * followed.zoom), red, 2), 'and draws it there');
    await page.evaluate(k => window.afrpReplay.setFrame(k - 2), k);
    check(JSON.stringify(await view()) === JSON.stringify(followed), 'one frame back, still in the middle, the view stays');
    await page.uncheck('#follow');
    await page.evaluate(() => window.afrpReplay.setFrame(0));
    check(JSON.stringify(await view()) === JSON.stringify(followed), 'unticked, the view stays as SimbotB 2 goes back to its start');
    await page.check('#follow');
    const again = await view();
    check(again.cx === rB0.x && again.cy === rB0.y, 'ticked again, the view centres on it (' + JSON.stringify(again) + ')');
    // zoomed in from the whole world with +, paused, the view keeps it (it zoomed about the middle and lost it until
    // the frame changed)
    await page.evaluate(() => { const R = window.afrpReplay; R.setView(1, R.header.bounds.x, R.header.bounds.y); });
    for (let i = 0; i < 4; i++) await page.keyboard.press('+');
    const plussed = await view();
    const seen = await page.evaluate(r => {
      const c = document.getElementById('world'), p = window.afrpReplay.worldToCanvas(r.x, r.y);
      return { p: p, middle: Math.abs(p[0] - c.width / 2) < 0.3 * c.width && Math.abs(p[1] - c.height / 2) < 0.3 * c.height };
    }, rB0);
    check(plussed.zoom > 4 && seen.middle,
          'zoomed in with + while paused, the view keeps it in its middle part (' + JSON.stringify([plussed, seen.p]) + ')');
    // a drag away from it stops following: the next frames leave the dragged view be
    await page.mouse.move(inner[0] + 300, inner[1] + 300);
    await page.mouse.down();
    await page.mouse.move(inner[0] + 200, inner[1] + 300, { steps: 4 });
    await page.mouse.up();
    await nextFrame();
    const away = await view();
    await page.evaluate(k => window.afrpReplay.setFrame(k - 1), k);
    check(!(await page.isChecked('#follow')) && JSON.stringify(await view()) === JSON.stringify(away) && away.cx !== again.cx,
          'a drag unticks follow, and the view stays where the drag left it');
    await page.check('#follow');
    await page.evaluate(k => { const R = window.afrpReplay; R.setView(1, R.header.bounds.x, R.header.bounds.y); R.setFrame(k - 1); }, k);
    await page.evaluate(() => window.afrpReplay.selectRobot(0));
    await page.check('#rays');

    // keyboard: arrows step, space plays and pauses
    await page.locator('#world').focus().catch(() => {});
    await page.evaluate(() => document.activeElement && document.activeElement.blur());
    await page.keyboard.press('ArrowLeft');
    check(await page.evaluate(() => window.afrpReplay.frame()) === info.n - 2, 'left arrow steps one frame back');
    await page.keyboard.press('ArrowRight');
    check(await page.evaluate(() => window.afrpReplay.frame()) === info.n - 1, 'right arrow steps one frame forward');
    await page.evaluate(() => window.afrpReplay.setFrame(0));
    await page.keyboard.press(' ');
    check(await page.evaluate(() => window.afrpReplay.playing()), 'space plays');
    await page.waitForFunction(() => window.afrpReplay.frame() > 0, null, { timeout: 30000 }).catch(() => {});
    await page.keyboard.press(' ');
    const after = await page.evaluate(() => ({ playing: window.afrpReplay.playing(), frame: window.afrpReplay.frame() }));
    check(!after.playing && after.frame > 0, 'space pauses, after time moved on (frame ' + after.frame + ')');

    // the picture for the docs: half-way, sightings on, SimbotA 1 selected
    await page.evaluate(() => { window.afrpReplay.setFrame(Math.floor(window.afrpReplay.frameCount() * 0.75)); });
    await page.check('#sightings');
    await page.evaluate(() => window.afrpReplay.selectRobot(0));
    await page.screenshot({ path: shotPath, fullPage: true });
    console.log('screenshot: ' + shotPath);

    check(errors.length === 0, 'no console errors' + (errors.length ? ': ' + errors.join(' | ') : ''));
    check(requests.length === 0, 'no network requests' + (requests.length ? ': ' + requests.join(' ') : ''));
});
