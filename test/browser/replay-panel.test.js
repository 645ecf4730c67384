// Loads an afrp replay page in headless Chromium and checks the robot's
// panel (#info) and the page's heading:
//   node replay-panel.test.js PAGE.html
// The page must be that of ReplayBrowserSpec's usabilityPage (see
// replay-usability.test.js): 60 s at 25 frames a second; SimbotA 1 prints
// "tick" every second, SimbotB 1 nothing; the command line ends in
// --world "worlds/<img src=x onerror=alert(1)>two.world".
// Checked:
// - the panel's messages are the robot's last 50 up to the frame, newest
//   first, at several frames, after a step back and after a jump with the
//   slider;
// - the newest message is in view in the panel, below the readings, at
//   1200, 600 and 360 pixels wide, also while playing;
// - a frame drawn reads no more of the log's messages late in the run than
//   early (the messages are indexed once, not gathered from frame 0 at
//   every frame drawn): counted with a getter on each robot-frame's
//   messages;
// - the heading names the run, as the title does, as text.
// Chromium: $CHROMIUM, else /usr/bin/chromium. Exits 0 when every check
// passes, 1 with the failures listed otherwise.
'use strict';
const { run, check } = require('./harness');

const heading = 'messages (up to now, newest first):';

run('node replay-panel.test.js PAGE.html', async (page, errors, open) => {
    await open();
    const R = (f, arg) => page.evaluate(f, arg);
    const n = await R(() => window.afrpReplay.frameCount());
    check(n === 1501, 'the page has the run\'s 1501 frames (' + n + ')');

    // the panel's messages as they should be: the robot's last 50 up to the frame, newest first
    const expected = (robot, frame) => R(([robot, frame]) => {
      const all = [];
      for (let j = 0; j <= frame; j++) {
        window.afrpReplay.frameData(j).robots[robot].messages.forEach(m => all.push('  [' + m[0].toFixed(2) + '] ' + m[1]));
      }
      const last = all.slice(-50).reverse();
      return last.length ? last : ['  none'];
    }, [robot, frame]);
    const shown = () => R(() => {
      const text = document.getElementById('info').textContent, lines = text.split('\n');
      return { frame: window.afrpReplay.frame(), messages: lines.slice(lines.indexOf('messages (up to now, newest first):') + 1),
               has: lines.includes('messages (up to now, newest first):'), first: lines[0] };
    });
    const same = async (robot, what) => {
      const s = await shown(), want = await expected(robot, s.frame);
      check(s.has && JSON.stringify(s.messages) === JSON.stringify(want),
            what + ': the panel has the robot\'s last ' + want.length + ' messages up to frame ' + s.frame + ', newest first (' +
            (s.has ? s.messages.length + ' shown, first "' + s.messages[0] + '", last "' + s.messages[s.messages.length - 1] + '"'
                   : 'no "' + heading + '"') + '; wanted first "' + want[0] + '")');
    };
    await R(() => window.afrpReplay.selectRobot(0));
    for (const f of [0, 10, 25, 26, 750, 1300, n - 1]) {
      await R(f => window.afrpReplay.setFrame(f), f);
      await same(0, 'SimbotA 1 at frame ' + f);
    }
    await R(() => window.afrpReplay.setFrame(751));
    await page.evaluate(() => document.activeElement && document.activeElement.blur());
    await page.keyboard.press('ArrowLeft');
    await same(0, 'a step back from frame 751');
    const slider = await page.locator('#slider').boundingBox();
    await page.mouse.click(slider.x + slider.width * 0.3, slider.y + slider.height / 2);
    const jumped = await R(() => window.afrpReplay.frame());
    check(jumped > 300 && jumped < 600, 'a click on the slider jumps to about 30% (frame ' + jumped + ')');
    await same(0, 'a jump with the slider');
    await page.mouse.click(slider.x + slider.width * 0.9, slider.y + slider.height / 2);
    await same(0, 'a jump with the slider forward');
    await R(() => window.afrpReplay.selectRobot(1));
    await same(1, 'SimbotB 1, which prints nothing');
    await R(() => window.afrpReplay.selectRobot(0));

    // the newest message in view in the panel, below the readings, whatever the window's width
    const inView = () => R(() => {
      const el = document.getElementById('info'), node = el.firstChild, text = node.textContent;
      const box = el.getBoundingClientRect(), top = box.top + el.clientTop, bottom = top + el.clientHeight;
      const lineBox = line => {
        const at = text.indexOf(line), range = document.createRange();
        range.setStart(node, at); range.setEnd(node, at + line.length);
        const rs = Array.from(range.getClientRects());
        return { top: Math.min(...rs.map(r => r.top)), bottom: Math.max(...rs.map(r => r.bottom)) };
      };
      // (the newest: the message line of the latest time, wherever the panel puts it)
      const lines = text.split('\n'), from = lines.findIndex(l => l.startsWith('messages ('));
      const time = l => Number((/^  \[([0-9.]+)\]/.exec(l) || [0, -1])[1]);
      const newest = lines.slice(from + 1).reduce((a, l) => time(l) > time(a) ? l : a, lines[from + 1]);
      const first = lineBox(lines[0]), last = lineBox(newest);
      return { frame: window.afrpReplay.frame(), newest: newest, width: el.clientWidth,
               newestInView: last.top >= top - 0.5 && last.bottom <= bottom + 0.5, firstInView: first.top >= top - 0.5 };
    });
    for (const [w, h] of [[1200, 800], [600, 800], [360, 740]]) {
      await page.setViewportSize({ width: w, height: h });
      for (const f of [750, n - 1]) {
        await R(f => window.afrpReplay.setFrame(f), f);
        const v = await inView();
        check(v.newestInView && v.firstInView && v.newest.startsWith('  [' + (f / 25).toFixed(2) + '] tick'),
              'at ' + w + ' by ' + h + ', frame ' + f + ', the newest message ("' + v.newest + '") is in view in the panel (' +
              v.width + ' pixels wide), and so is its first line (' + JSON.stringify(v) + ')');
      }
      // while playing (at 4x, for a second)
      await R(() => { window.afrpReplay.setFrame(500); window.afrpReplay.play(); });
      await page.selectOption('#speed', '4');
      await page.waitForTimeout(1000);
      const playing = await inView();
      await R(() => window.afrpReplay.pause());
      await page.selectOption('#speed', '1');
      check(playing.newestInView && playing.frame > 520, 'at ' + w + ' wide, played on to frame ' + playing.frame +
            ', the newest message ("' + playing.newest + '") is still in view');
    }
    await page.setViewportSize({ width: 1200, height: 800 });

    // the work of a frame drawn: the robot-frames' messages read, late in the run and early
    await R(() => window.afrpReplay.setFrame(window.afrpReplay.frameCount() - 1));   // (all indexed first)
    const reads = await R(() => {
      const A = window.afrpReplay;
      let count = 0;
      for (let j = 0; j < A.frameCount(); j++) {
        A.frameData(j).robots.forEach(r => {
          const ms = r.messages;
          Object.defineProperty(r, 'messages', { configurable: true, get: () => { count++; return ms; } });
        });
      }
      const readsOf = act => { count = 0; act(); return count; };
      A.selectRobot(0);
      return { at10: readsOf(() => A.setFrame(10)), at1490: readsOf(() => A.setFrame(1490)),
               back: readsOf(() => A.setFrame(1489)), jump: readsOf(() => A.setFrame(20)),
               at1500: readsOf(() => A.setFrame(1500)) };
    });
    check(reads.at1490 <= reads.at10 && reads.back <= reads.at10 && reads.at1500 <= reads.at10 && reads.at10 <= 2,
          'a frame drawn reads no more messages at frame 1490 or 1500, a step back or a jump back than at frame 10, ' +
          'and at most 2 (' + JSON.stringify(reads) + ')');

    // the heading: the run, as the title names it, as text
    const head = await R(() => {
      const h = document.getElementsByTagName('h1')[0];
      return { text: h.textContent, children: h.children.length, imgs: document.querySelectorAll('img').length, title: document.title };
    });
    check(head.text === 'afrp replay: simbot, world <img src=x onerror=alert(1)>two.world' && head.children === 0 &&
          head.imgs === 0, 'the heading names the run\'s program and world, as text (' + JSON.stringify(head) + ')');
    check(head.title === 'simbot, world <img src=x onerror=alert(1)>two.world - afrp replay', 'as the title does');

    check(errors.length === 0, 'no errors on the page' + (errors.length ? ': ' + errors.join('; ') : ''));
});
