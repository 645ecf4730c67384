// Loads an afrp replay page of a world of any size in headless Chromium and
// checks that it shows the whole world:
//   node replay-size.test.js PAGE.html
// The canvas keeps the world's proportions with 620 pixels on its long side
// (plus a 10-pixel margin), the world's corners map to the margin's inner
// corners, every robot of the first frame lies inside the world's rectangle,
// and the first robot of each type, when big enough to sample (4 pixels in
// radius), is drawn in its type's colour where the log puts it.
// Chromium: $CHROMIUM, else /usr/bin/chromium. Exits 0 when every check
// passes, 1 with the failures listed otherwise.
'use strict';
const { run, check, near } = require('./harness');

const typeColours = { SimbotA: [30, 90, 220], SimbotB: [215, 40, 40] };

run('node replay-size.test.js PAGE.html', async (page, errors, open) => {
    await open();
    await page.uncheck('#rays');
    const v = await page.evaluate(() => {
      const c = document.getElementById('world');
      const h = window.afrpReplay.header, b = h.bounds;
      const x0 = b.x - b.width / 2, x1 = b.x + b.width / 2, y0 = b.y - b.height / 2, y1 = b.y + b.height / 2;
      return { w: c.width, h: c.height, bounds: b, types: h.robots.map(r => r.type), radius: h.robots.map(r => r.radius),
               topLeft: window.afrpReplay.worldToCanvas(x0, y1), bottomRight: window.afrpReplay.worldToCanvas(x1, y0),
               robots: window.afrpReplay.frameData(0).robots.map(r => ({ x: r.x, y: r.y, heading: r.heading,
                                                                       at: window.afrpReplay.worldToCanvas(r.x, r.y) })) };
    });
    const s = Math.min(620 / v.bounds.width, 620 / v.bounds.height);
    const what = v.bounds.width + ' by ' + v.bounds.height + ' m world';
    check(v.w === Math.round(v.bounds.width * s + 20) && v.h === Math.round(v.bounds.height * s + 20) && Math.max(v.w, v.h) === 640,
          'the canvas of the ' + what + ' is ' + v.w + ' by ' + v.h + ' pixels: its proportions, 640 on the long side');
    check(near(v.topLeft, [10, 10], 0.5) && near(v.bottomRight, [v.w - 10, v.h - 10], 0.5),
          'the world\'s corners are the margin\'s inner corners');
    check(v.robots.length > 0 && v.robots.every(r => r.at[0] >= 10 && r.at[0] <= v.w - 10 && r.at[1] >= 10 && r.at[1] <= v.h - 10),
          'every robot (' + v.robots.length + ') is inside the world\'s rectangle on the canvas');
    const seen = {};
    for (let i = 0; i < v.robots.length; i++) {
      const r = v.robots[i], radiusPx = v.radius[i] * s;
      if (seen[v.types[i]] || radiusPx < 4 || !typeColours[v.types[i]]) continue;
      seen[v.types[i]] = true;
      // a point of the body behind the centre (the heading mark runs forward from it)
      const px = await page.evaluate(([x, y]) => Array.from(document.getElementById('world').getContext('2d')
                                       .getImageData(Math.round(x), Math.round(y), 1, 1).data.slice(0, 3)),
                                     [r.at[0] - 0.5 * radiusPx * Math.cos(r.heading), r.at[1] + 0.5 * radiusPx * Math.sin(r.heading)]);
      check(near(px, typeColours[v.types[i]], 40), v.types[i] + ' ' + i + ' at (' + r.x + ', ' + r.y + ') is drawn there (' + px + ')');
    }
    check(errors.length === 0, 'no script errors' + (errors.length ? ': ' + errors.join('; ') : ''));
});
