// Loads the page of a run of which a test's property was decided false,
// as afrp-test's forAllRuns writes it, in headless Chromium (1200 by 800):
//   node replay-verdict.test.js PAGE.html [FAILED.html]
// The page must be ReplayBrowserSpec's verdictPage: 10 s at 25 frames a
// second, its summary's falsified at t = 4.01 s with the line "decided
// false at t = 4.01 (step 401)". Checked:
// - it opens at frame 100 (t = 4.00 s), the frame nearest the instant,
//   the slider there (it opened at frame 0);
// - its heading and its summary line say "FAILED: " and the line;
// - the slider has a mark at that frame, which stays when the frame
//   changes;
// - stepping and playing work from there;
// - its summary line counts "2 robots".
// FAILED.html, if given, must be ReplayBrowserSpec's failedPage: one
// robot, a run of 2 s whose controller failed, its summary's failure two
// lines. Checked: the heading says "FAILED: " and the failure's first
// line (it said nothing of the failure), the summary line says the whole
// failure and counts "1 robot" (it said "1 robots").
// Chromium: $CHROMIUM, else /usr/bin/chromium. Exits 0 when every check
// passes, 1 with the failures listed otherwise.
'use strict';
const path = require('path');
const { run, check } = require('./harness');

run('node replay-verdict.test.js PAGE.html', async (page, errors, open) => {
    await open();
    const R = (f, arg) => page.evaluate(f, arg);
    const said = 'FAILED: decided false at t = 4.01 (step 401)';
    const opened = await R(() => ({
      frame: window.afrpReplay.frame(), marked: window.afrpReplay.falsifiedFrame,
      slider: document.getElementById('slider').value, time: document.getElementById('time').textContent,
      heading: document.querySelector('h1').textContent, meta: document.getElementById('meta').textContent }));
    check(opened.frame === 100 && opened.slider === '100',
          'the page opens at frame 100, the nearest t = 4.01 s (frame ' + opened.frame + ', slider ' + opened.slider + ')');
    check(opened.marked === 100, 'falsifiedFrame is 100 (' + opened.marked + ')');
    check(/^t = 4\.00 s/.test(opened.time), 'its time reads t = 4.00 s (' + JSON.stringify(opened.time) + ')');
    check(opened.heading === 'afrp replay: afrp-test - ' + said, 'the heading says it (' + JSON.stringify(opened.heading) + ')');
    check(opened.meta.endsWith('; ' + said), 'the summary line says it (' + JSON.stringify(opened.meta) + ')');

    const mark = () => R(() => {
      const s = document.getElementById('slider'), list = s.list;
      return list ? Array.from(list.options).map(o => o.value) : null;
    });
    const before = await mark();
    check(JSON.stringify(before) === '["100"]', 'the slider has one mark, at frame 100 (' + JSON.stringify(before) + ')');

    await page.keyboard.press('ArrowLeft');
    const back = await R(() => window.afrpReplay.frame());
    check(back === 99, 'a step back goes to frame 99 (' + back + ')');
    await R(() => window.afrpReplay.setFrame(200));
    check(JSON.stringify(await mark()) === '["100"]', 'the mark stays at frame 100 on another frame');
    await R(() => window.afrpReplay.setFrame(100));
    await R(() => window.afrpReplay.play());
    await page.waitForTimeout(300);
    const played = await R(() => ({ frame: window.afrpReplay.frame(), playing: window.afrpReplay.playing() }));
    await R(() => window.afrpReplay.pause());
    check(played.playing && played.frame > 100, 'it plays on from there (frame ' + played.frame + ' after 0.3 s)');
    check(/, 2 robots; /.test(opened.meta), 'the summary line counts 2 robots (' + JSON.stringify(opened.meta) + ')');

    const failedPath = process.argv[3];
    if (failedPath) {
      await page.goto('file://' + path.resolve(failedPath));
      await page.waitForFunction(() => window.afrpReplay !== undefined, null, { timeout: 10000 });
      const failed = await R(() => ({ heading: document.querySelector('h1').textContent,
                                      meta: document.getElementById('meta').textContent }));
      const first = "SimbotA 1's controller failed at t = 2.00 s: boom";
      check(failed.heading === 'afrp replay: afrp-test - FAILED: ' + first,
            'a failed run\'s heading says its failure\'s first line (' + JSON.stringify(failed.heading) + ')');
      check(failed.meta.endsWith('; FAILED: ' + first + '\nat the second line'),
            'its summary line says the whole failure (' + JSON.stringify(failed.meta) + ')');
      check(/, 1 robot; /.test(failed.meta), 'its summary line counts 1 robot (' + JSON.stringify(failed.meta) + ')');
    }
    check(errors.length === 0, 'no console errors' + (errors.length ? ': ' + errors.join('; ') : ''));
});
