// Loads an afrp replay page in headless Chromium (1200 by 800) and checks
// what a user's audit of the page found wanting:
//   node replay-usability.test.js PAGE.html
// The page must be that of ReplayBrowserSpec's usabilityPage: 60 s at 25
// frames a second in the notes' world; SimbotA 1 and SimbotB 1 (the same
// id); SimbotA 1 printing "tick" every second; a score "seconds" rising
// every second; SimbotB 1 bumping into a wall; and the command line
// simbot --world "worlds/<img src=x onerror=alert(1)>two.world" --seconds 60.
// Checked:
// - the side panel sits beside the canvas at 1200 by 800, and below it
//   on a narrow window;
// - the events panel shows the newest line up to the frame, last and
//   scrolled into view, also after a step back, and has the robots'
//   messages, the scores and the bumps;
// - the slider held while playing keeps its frame, and playing goes on
//   from where it was let go (a paused page stays paused);
// - the speeds go up to 32x, and the time runs at the speed chosen;
// - keys with Ctrl, Meta or Alt are left to the browser;
// - the title names the run's program and world file, as text;
// - SimbotA 1 and SimbotB 1 are labelled A1 and B1.
// Chromium: $CHROMIUM, else /usr/bin/chromium. Exits 0 when every check
// passes, 1 with the failures listed otherwise.
'use strict';
const { run, check } = require('./harness');

run('node replay-usability.test.js PAGE.html', async (page, errors, open) => {
    await open();
    const R = (f, arg) => page.evaluate(f, arg);
    const n = await R(() => window.afrpReplay.frameCount());
    check(n === 1501, 'the page has the run\'s 1501 frames (' + n + ')');

    // the side panel beside the canvas at 1200 by 800, whatever the frame and the selection
    const layout = () => R(() => {
      const box = id => { const r = document.getElementById(id).getBoundingClientRect();
                          return { left: r.left, right: r.right, top: r.top, bottom: r.bottom, width: r.width }; };
      return { canvas: box('world'), side: box('side'), scroll: document.documentElement.scrollWidth,
               page: document.documentElement.clientWidth };
    });
    const beside = l => l.side.left >= l.canvas.right && l.side.top < l.canvas.bottom && l.side.right <= l.page &&
                        l.scroll <= l.page;
    const sides = [];
    let allBeside = true;
    for (const [frame, robot] of [[0, -1], [750, 0], [n - 1, 1], [n - 1, -1]]) {
      await R(([f, r]) => { window.afrpReplay.setFrame(f); window.afrpReplay.selectRobot(r); }, [frame, robot]);
      const l = await layout();
      sides.push(Math.round(l.side.left) + '+' + Math.round(l.side.width) + '@' + Math.round(l.side.top));
      if (!beside(l)) allBeside = false;
    }
    const wide = await layout();
    check(allBeside, 'at 1200 by 800 the side panel is beside the canvas, within the window, at every frame tried ' +
          '(canvas right ' + Math.round(wide.canvas.right) + ', top ' + Math.round(wide.canvas.top) + '; panel left+width@top: ' +
          sides.join(', ') + ')');
    check(wide.side.width <= 420.5, 'and is at most 420 pixels wide (' + wide.side.width + ')');
    await page.setViewportSize({ width: 700, height: 800 });
    const narrow = await layout();
    check(narrow.side.top >= narrow.canvas.bottom && narrow.side.right <= narrow.page,
          'at 700 by 800 it is below the canvas, within the window (top ' + Math.round(narrow.side.top) + ', canvas bottom ' +
          Math.round(narrow.canvas.bottom) + ')');
    await page.setViewportSize({ width: 1200, height: 800 });

    // the events panel: the newest line up to the frame in view, after a step back too
    const panel = () => R(() => {
      const el = document.getElementById('events'), lines = el.textContent.split('\n');
      const R = window.afrpReplay, k = R.frame();
      // the newest time of an event or a message up to the frame
      let newest = -1;
      for (let j = 0; j <= k; j++) {
        const f = R.frameData(j);
        f.events.forEach(e => { newest = Math.max(newest, e.t); });
        f.robots.forEach(r => r.messages.forEach(m => { newest = Math.max(newest, m[0]); }));
      }
      return { frame: k, text: el.textContent, last: lines[lines.length - 1], count: lines.length, newest: newest,
               atEnd: el.scrollTop + el.clientHeight >= el.scrollHeight - 1, overflows: el.scrollHeight > el.clientHeight + 20 };
    });
    const newestShown = p => p.last.startsWith('[' + p.newest.toFixed(2) + ']') && p.atEnd && p.overflows;
    const describe = p => 'frame ' + p.frame + ', ' + p.count + ' lines, newest ' + p.newest.toFixed(2) + ', last "' + p.last +
                          '", scrolled to the end: ' + p.atEnd;
    await R(() => window.afrpReplay.setFrame(750));
    const at30 = await panel();
    check(newestShown(at30), 'at 30 s the events panel shows its newest line, last and in view (' + describe(at30) + ')');
    check(at30.count === 30, 'it keeps the last 30 lines (' + at30.count + ')');
    check(at30.text.includes('[30.00] SimbotA 1: tick'), 'the robots\' messages are among the events ("[30.00] SimbotA 1: tick")');
    check(at30.text.includes('[30.00] score: seconds scores: 30'), 'and the scores ("[30.00] score: seconds scores: 30")');
    await page.evaluate(() => document.activeElement && document.activeElement.blur());
    await page.keyboard.press('ArrowLeft');
    const back = await panel();
    check(back.frame === 749 && !back.text.includes('[30.00]') && newestShown(back),
          'a step back drops the lines of 30 s and still shows the newest, last and in view (' + describe(back) + ')');
    await R(() => window.afrpReplay.setFrame(1200));
    await R(() => window.afrpReplay.setFrame(400));
    const jumped = await panel();
    check(newestShown(jumped), 'so does a jump back (' + describe(jumped) + ')');
    const bump = await R(() => {
      const R = window.afrpReplay;
      for (let j = 0; j < R.frameCount(); j++) {
        const e = R.frameData(j).events.find(e => e.kind === 'bump');
        if (e) { R.setFrame(j); return { frame: j, text: '[' + e.t.toFixed(2) + '] bump: ' + e.text }; }
      }
      return null;
    });
    const atBump = await panel();
    check(bump !== null && atBump.last === bump.text, 'a bump is the newest line at its frame (' + JSON.stringify(bump) + ')');

    // the slider held while playing: the frame stays where the hand puts it; let go, playing goes on from there
    const slider = await page.locator('#slider').boundingBox();
    const along = f => [slider.x + slider.width * f, slider.y + slider.height / 2];
    const now = () => R(() => ({ frame: window.afrpReplay.frame(), playing: window.afrpReplay.playing(),
                                 value: Number(document.getElementById('slider').value),
                                 t: window.afrpReplay.frameData().t }));
    await R(() => { window.afrpReplay.setFrame(0); window.afrpReplay.play(); });
    await page.waitForTimeout(300);
    await page.mouse.move(...along(0.5));
    await page.mouse.down();
    await page.mouse.move(...along(0.4), { steps: 4 });
    const held0 = await now();
    await page.waitForTimeout(800);
    const held1 = await now();
    check(held0.playing && held1.playing && held1.frame === held0.frame && held1.value === held0.value && held1.value === held1.frame,
          'while the slider is held, playing moves neither the frame nor the slider (' + JSON.stringify([held0, held1]) + ')');
    await page.mouse.up();
    await page.waitForTimeout(600);
    const goneOn = await now();
    check(goneOn.playing && goneOn.t - held1.t > 0.2 && goneOn.t - held1.t < 1.5,
          'let go, playing goes on from where it was left (' + (goneOn.t - held1.t).toFixed(2) + ' s on from ' +
          held1.t.toFixed(2) + ' s after 0.6 s)');
    await R(() => window.afrpReplay.pause());
    await page.mouse.move(...along(0.6));
    await page.mouse.down();
    await page.mouse.move(...along(0.7), { steps: 4 });
    await page.waitForTimeout(300);
    await page.mouse.up();
    await page.waitForTimeout(300);
    const paused = await now();
    check(!paused.playing && paused.frame === paused.value && Math.abs(paused.frame / (n - 1) - 0.7) < 0.05,
          'paused, the slider dragged leaves the page paused at the frame it was let go at (' + JSON.stringify(paused) + ')');

    // the speeds: up to 32x, and the time runs at the speed chosen
    const speeds = await R(() => Array.from(document.getElementById('speed').options).map(o => o.value));
    check(['8', '16', '32'].every(v => speeds.includes(v)), 'the speeds go up to 32x (' + speeds.join(', ') + ')');
    for (const v of ['8', '32']) {
      if (!speeds.includes(v)) continue;
      await page.selectOption('#speed', v);
      // (both ends taken in animation frames, after the page's own tick
      // of that frame, whose time it plays by: a frame the browser is
      // late to draw, on a loaded machine, delays both alike)
      const rate = await R(() => new Promise(done => {
        const R = window.afrpReplay;
        R.setFrame(0); R.play();
        let t0 = null, s0 = null;
        const sample = ts => {
          if (t0 === null) { t0 = ts; s0 = R.frameData().t; }
          if (ts - t0 >= 1000 || !R.playing()) done({ real: (ts - t0) / 1000, sim: R.frameData().t - s0, playing: R.playing() });
          else requestAnimationFrame(sample);
        };
        requestAnimationFrame(() => requestAnimationFrame(sample));
      }));
      await R(() => window.afrpReplay.pause());
      const r = rate.sim / rate.real;
      check(Math.abs(r / Number(v) - 1) < 0.15, 'at ' + v + 'x the time runs ' + r.toFixed(2) + ' times as fast as the clock (' +
            rate.sim.toFixed(2) + ' s in ' + rate.real.toFixed(3) + ' s)');
    }
    await page.selectOption('#speed', '1');

    // keys with Ctrl, Meta or Alt are the browser's: the page neither acts on them nor takes them
    await page.evaluate(() => {
      document.activeElement && document.activeElement.blur();
      window.__taken = [];
      window.addEventListener('keydown', e => { if (e.defaultPrevented) window.__taken.push(e.key); });
      window.afrpReplay.setFrame(100); window.afrpReplay.setView(2, 0, 0);
    });
    const state = () => R(() => ({ frame: window.afrpReplay.frame(), zoom: window.afrpReplay.view().zoom,
                                   playing: window.afrpReplay.playing(), taken: window.__taken.slice() }));
    const before = await state();
    const keys = ['Control+0', 'Control+Equal', 'Control+Minus', 'Control+ArrowRight', 'Control+ArrowLeft', 'Control+Space',
                  'Meta+ArrowRight', 'Meta+0', 'Alt+0', 'Alt+Equal'];
    const moved = [];
    for (const k of keys) {
      await page.keyboard.press(k);
      const s = await state();
      if (s.frame !== before.frame || s.zoom !== before.zoom || s.playing || s.taken.length) moved.push(k + ' -> ' + JSON.stringify(s));
      if (s.playing) await R(() => window.afrpReplay.pause());
    }
    check(moved.length === 0, 'keys with Ctrl, Meta or Alt neither step, zoom nor play, and are not taken from the browser' +
          (moved.length ? ' (' + moved.join('; ') + ')' : ''));
    await page.keyboard.press('ArrowRight');
    await page.keyboard.press('0');
    const plain = await state();
    check(plain.frame === 101 && plain.zoom === 1, 'without them, the keys still step and fit (' + JSON.stringify(plain) + ')');

    // the title: the program and the (last) world file, as text
    const title = await R(() => ({ title: document.title, imgs: document.querySelectorAll('img').length }));
    check(title.title === 'simbot, world <img src=x onerror=alert(1)>two.world - afrp replay' && title.imgs === 0,
          'the title names the run\'s program and world, as text (' + JSON.stringify(title) + ')');

    // the labels of SimbotA 1 and SimbotB 1 differ (the texts the canvas is given, caught)
    await R(() => window.afrpReplay.selectRobot(-1));
    const labels = await R(() => {
      const proto = CanvasRenderingContext2D.prototype, fillText = proto.fillText, texts = [];
      proto.fillText = function (t) { texts.push(String(t)); return fillText.apply(this, arguments); };
      try { window.afrpReplay.setFrame(0); } finally { proto.fillText = fillText; }
      return texts;
    });
    check(labels.length === 2 && labels[0] !== labels[1], 'SimbotA 1 and SimbotB 1 are drawn with different labels (' +
          JSON.stringify(labels) + ')');
    check(JSON.stringify(labels) === '["A1","B1"]', 'A1 and B1');
    await R(() => window.afrpReplay.selectRobot(1));
    const head = (await page.locator('#info').textContent()).split('\n')[0];
    check(head.startsWith('SimbotB 1 (drawn B1)'), 'the side panel names SimbotB 1 and its label (' + head + ')');
    await R(() => window.afrpReplay.selectRobot(-1));

    // the score "seconds" after the time: 5 at t = 5.00 s (frame 125) (a page without scores:
    // replay-controls.test.js)
    await R(() => window.afrpReplay.setFrame(125));
    const timeLine = await page.locator('#time').textContent();
    check(/^t = 5\.00 s\s+\(frame 125 of \d+\)\s+score: seconds 5$/.test(timeLine), 'the time line shows the score (' + timeLine + ')');

    check(errors.length === 0, 'no errors on the page' + (errors.length ? ': ' + errors.join('; ') : ''));
});
