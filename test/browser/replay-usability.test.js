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

    check(errors.length === 0, 'no errors on the page' + (errors.length ? ': ' + errors.join('; ') : ''));
});
