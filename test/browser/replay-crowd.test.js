// Loads an afrp replay page of a crowd in a big world in headless Chromium
// and checks how it draws many small robots:
//   node replay-crowd.test.js PAGE.html
// The page must hold more than 200 robots, each under 1.5 pixels in radius
// when the whole world is in view, and some walls and blocks (shown at
// least a pixel wide and tall). Then every robot is drawn (at least 1.5
// pixels in radius, so that it shows) and no id but the selected robot's;
// zoomed in until the robots are 8 pixels across, the robots in view are
// drawn, each with its id, and those out of view are skipped.
// Chromium: $CHROMIUM, else /usr/bin/chromium. Exits 0 when every check
// passes, 1 with the failures listed otherwise.
'use strict';
const { run, check, near } = require('./harness');

const background = [240, 240, 230];

run('node replay-crowd.test.js PAGE.html', async (page, errors, open) => {
    await open();
    await page.uncheck('#rays');
    await page.uncheck('#trails');
    // the robots of the last frame: where they are on the canvas, and the pixel of each half its
    // radius behind its centre (the heading mark runs forward from the centre)
    const look = () => page.evaluate(() => {
      const R = window.afrpReplay, c = document.getElementById('world'), g = c.getContext('2d');
      const scale = R.worldToCanvas(1, 0)[0] - R.worldToCanvas(0, 0)[0];
      return { w: c.width, h: c.height, view: R.view(), drawn: R.drawn(), scale: scale,
               robots: R.frameData().robots.map((r, i) => {
                 const p = R.worldToCanvas(r.x, r.y), back = 0.5 * Math.max(R.header.robots[i].radius * scale, 1.5);
                 const q = [p[0] - back * Math.cos(r.heading), p[1] + back * Math.sin(r.heading)];
                 return { at: p, pixel: Array.from(g.getImageData(Math.round(q[0]), Math.round(q[1]), 1, 1).data.slice(0, 3)) };
               }) };
    });
    const n = await page.evaluate(() => { const R = window.afrpReplay; R.setFrame(R.frameCount() - 1); return R.header.robots.length; });
    const radius = await page.evaluate(() => window.afrpReplay.header.robots[0].radius);
    const fit = await look();
    check(n > 200 && radius * fit.scale < 1.5, 'the page is a crowd of ' + n + ' robots, ' + (radius * fit.scale).toFixed(2) +
          ' pixels in radius in the whole world\'s view');
    check(fit.drawn.robots === n && fit.drawn.labels === 0, 'the whole world\'s view draws every robot and no id (' + JSON.stringify(fit.drawn) + ')');
    // walls (0.1 m thick, a fifth of a pixel here) and blocks are drawn at least a pixel wide and tall:
    // the darkest pixel around each one's centre is well darker than the floor
    const still = await page.evaluate(() => {
      const R = window.afrpReplay, g = document.getElementById('world').getContext('2d');
      return R.header.walls.concat(R.header.blocks).map(o => {
        const p = R.worldToCanvas(o.x, o.y), d = g.getImageData(Math.floor(p[0]) - 1, Math.floor(p[1]) - 1, 3, 3).data;
        let darkest = 255;
        for (let k = 0; k < 9; k++) darkest = Math.min(darkest, d[4 * k + 1]);
        return darkest;
      });
    });
    check(still.length >= 10 && still.every(g => g <= background[1] - 50),
          'every wall and block shows in the whole world\'s view (darkest pixels ' + still.join(' ') + ')');
    const blank = fit.robots.filter(r => near(r.pixel, background, 30)).length;
    check(blank === 0, 'every robot shows (' + blank + ' look like the floor)');
    await page.evaluate(() => window.afrpReplay.selectRobot(7));
    const selected = await page.evaluate(() => window.afrpReplay.drawn());
    check(selected.robots === n && selected.labels === 1, 'selected, a robot\'s id is drawn (' + JSON.stringify(selected) + ')');
    await page.evaluate(() => window.afrpReplay.selectRobot(-1));

    // zoomed in about the world's middle until a robot is 8 pixels across
    await page.evaluate(([z]) => { const R = window.afrpReplay, b = R.header.bounds; R.setView(z, b.x, b.y); }, [4 / (radius * fit.scale)]);
    const zoomed = await look();
    const inView = zoomed.robots.filter(r => r.at[0] >= 10 && r.at[0] <= zoomed.w - 10 && r.at[1] >= 10 && r.at[1] <= zoomed.h - 10);
    const nearby = zoomed.robots.filter(r => r.at[0] >= -5 * zoomed.scale && r.at[0] <= zoomed.w + 5 * zoomed.scale &&
                                             r.at[1] >= -5 * zoomed.scale && r.at[1] <= zoomed.h + 5 * zoomed.scale);
    check(inView.length > 0 && zoomed.drawn.robots >= inView.length && zoomed.drawn.robots <= nearby.length && zoomed.drawn.robots < n,
          'zoomed in, the robots in view are drawn and the others skipped (' + zoomed.drawn.robots + ' drawn, ' +
          inView.length + ' in view, ' + nearby.length + ' within 5 m of it, of ' + n + ')');
    check(zoomed.drawn.labels === zoomed.drawn.robots, 'each with its id, now 8 pixels across');
    const wrong = inView.filter(r => near(r.pixel, background, 30)).length;
    check(wrong === 0, 'every robot in view is drawn where the log puts it (' + wrong + ' are not)');
    check(errors.length === 0, 'no script errors' + (errors.length ? ': ' + errors.join('; ') : ''));
});
