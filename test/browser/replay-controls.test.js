// Loads an afrp replay page in headless Chromium (1200 by 800) and checks
// its controls with the keyboard and on a narrow window:
//   node replay-controls.test.js PAGE.html
// The page must be that of the test fixture (test/AFrobRobotSim/LogFixture.hs).
// Checked:
// - Space on a tick box or a button reached with Tab is the control's:
//   it ticks the box ("trails") or presses the button ("Fit"), and does
//   not play;
// - Space after a click on a button or a tick box (the focus left on it,
//   also when Tab had taken it there) plays, as elsewhere on the page, and
//   neither steps again nor ticks;
// - on a window 360 pixels wide each tick box's label is on one line.
// Chromium: $CHROMIUM, else /usr/bin/chromium. Exits 0 when every check
// passes, 1 with the failures listed otherwise.
'use strict';
const { run, check } = require('./harness');

run('node replay-controls.test.js PAGE.html', async (page, errors, open) => {
    await open();
    const R = (f, arg) => page.evaluate(f, arg);
    const state = () => R(() => ({ playing: window.afrpReplay.playing(), frame: window.afrpReplay.frame(),
                                   trails: document.getElementById('trails').checked, zoom: window.afrpReplay.view().zoom,
                                   focus: document.activeElement && document.activeElement.id }));
    // Tab from where the focus is to an element, as a user of the keyboard goes
    const tabTo = async id => {
      for (let k = 0; k < 30; k++) {
        if (await R(() => document.activeElement && document.activeElement.id) === id) return true;
        await page.keyboard.press('Tab');
      }
      return false;
    };

    await R(() => { document.activeElement && document.activeElement.blur(); window.afrpReplay.setFrame(5); });
    check(await tabTo('trails'), 'Tab reaches the "trails" tick box');
    await page.keyboard.press('Space');
    const ticked = await state();
    check(!ticked.trails && !ticked.playing && ticked.frame === 5, 'Space on it, reached with Tab, unticks it and does not play (' +
          JSON.stringify(ticked) + ')');
    await page.keyboard.press('Space');
    const again = await state();
    check(again.trails && !again.playing, 'and again ticks it (' + JSON.stringify(again) + ')');

    await R(() => window.afrpReplay.setView(2, 0, 0));
    check(await tabTo('fit'), 'Tab reaches the "Fit" button');
    await page.keyboard.press('Space');
    const fitted = await state();
    check(fitted.zoom === 1 && !fitted.playing && fitted.frame === 5, 'Space on it, reached with Tab, fits the view and does not play (' +
          JSON.stringify(fitted) + ')');

    // after a click the focus stays on the control, but Space plays
    await R(() => { window.afrpReplay.pause(); window.afrpReplay.setFrame(5); });
    await page.click('#fwd');
    const stepped = await state();
    await page.keyboard.press('Space');
    const played = await state();
    await R(() => window.afrpReplay.pause());
    check(stepped.frame === 6 && stepped.focus === 'fwd' && played.playing,
          'Space after a click on the step button plays (a press of the button would have paused it) (' + JSON.stringify([stepped, played]) + ')');
    await page.click('#trails');
    const clicked = await state();
    await page.keyboard.press('Space');
    const playedBox = await state();
    await R(() => window.afrpReplay.pause());
    check(!clicked.trails && clicked.focus === 'trails' && playedBox.playing && !playedBox.trails,
          'Space after a click on a tick box plays, and leaves the box as the click left it (' + JSON.stringify([clicked, playedBox]) + ')');
    await page.click('#trails');
    // (a box reached with Tab, then clicked: the hand is on the mouse, Space plays)
    await R(() => document.activeElement && document.activeElement.blur());
    check(await tabTo('trails'), 'Tab reaches the "trails" tick box again');
    await page.click('#trails');
    const tabbedClicked = await state();
    await page.keyboard.press('Space');
    const thenSpace = await state();
    await R(() => window.afrpReplay.pause());
    check(!tabbedClicked.trails && thenSpace.playing && !thenSpace.trails,
          'reached with Tab, then clicked, Space plays and leaves the box (' + JSON.stringify([tabbedClicked, thenSpace]) + ')');
    await page.click('#trails');

    // each label on one line on a narrow window
    await page.setViewportSize({ width: 360, height: 740 });
    const broken = await R(() => Array.from(document.querySelectorAll('label'))
      .filter(l => l.getClientRects().length > 1).map(l => l.textContent.trim()));
    check(broken.length === 0, 'at 360 pixels wide every tick box\'s label is on one line' +
          (broken.length ? ' (broken: ' + broken.join(', ') + ')' : ''));
    // a run that keeps no scores shows none after the time
    const timeLine = await page.locator('#time').textContent();
    check(/^t = \d+\.\d\d s\s+\(frame \d+ of \d+\)$/.test(timeLine), 'the time line has no score (' + timeLine + ')');

    check(errors.length === 0, 'no errors on the page' + (errors.length ? ': ' + errors.join('; ') : ''));
});
