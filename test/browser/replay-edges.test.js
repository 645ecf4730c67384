// Loads an afrp replay page in headless Chromium and checks what sits at
// the page's edges:
//   node replay-edges.test.js PAGE.html
// The page must be ReplayBrowserSpec's edgesPage: a 1 s run in the
// notes' 10 by 10 m world of SimbotA 1 at its right edge, SimbotA 22 in
// its top right corner, SimbotB 1 at its top edge and SimbotB 22 in its
// bottom right corner (labelled A1, A22, B1, B22); its command line
// names the world file worlds/a\b.world. Checked:
// - every robot's label lies within the canvas (zoomed in: within the
//   world's rectangle, which clips what is drawn), and is drawn there;
//   at zoom 1 nothing dark is drawn right of the world's edge (a label
//   the canvas's edge cut off drew its first letter there);
// - the help text and the summary line break between words, never inside
//   one, at widths from 320 to 1400 pixels;
// - the play button keeps its width, and the controls after it their
//   places, when Play becomes Pause and back, at 1200 and at 600 pixels;
// - the title names the world file a\b.world whole ('\' is no folder
//   separator);
// - the page opens at frame 0, with no mark on the slider.
// Chromium: $CHROMIUM, else /usr/bin/chromium. Exits 0 when every check
// passes, 1 with the failures listed otherwise.
'use strict';
const { run, check } = require('./harness');

run('node replay-edges.test.js PAGE.html', async (page, errors, open) => {
    await open();
    const R = (f, arg) => page.evaluate(f, arg);
    const opened = await R(() => ({ frame: window.afrpReplay.frame(), falsified: window.afrpReplay.falsifiedFrame,
                                    list: document.getElementById('slider').list }));

    // Each label's box (the page's drawn().labelBoxes) against the area
    // that shows: the canvas at zoom 1, the world's rectangle zoomed in;
    // and how many dark pixels (the labels' near-black) lie in the box.
    const labels = () => R(() => {
      const A = window.afrpReplay, c = document.getElementById('world'), g = c.getContext('2d');
      // (the page's margin round the world: 10 CSS pixels, in the canvas's pixels)
      const inset = A.view().zoom > 1 ? 10 * Math.min(2, Math.max(1, window.devicePixelRatio || 1)) : 0;
      const data = g.getImageData(0, 0, c.width, c.height).data;
      const dark = (x0, y0, x1, y1) => {
        let n = 0;
        for (let y = Math.max(0, Math.floor(y0)); y < Math.min(c.height, Math.ceil(y1)); y++)
          for (let x = Math.max(0, Math.floor(x0)); x < Math.min(c.width, Math.ceil(x1)); x++) {
            const k = 4 * (y * c.width + x);
            if (Math.max(data[k], data[k + 1], data[k + 2]) < 100) n++;
          }
        return n;
      };
      const boxes = (A.drawn().labelBoxes || []).map(b => ({
        robot: b.robot, inside: b.x >= inset - 0.5 && b.y >= inset - 0.5 && b.x + b.width <= c.width - inset + 0.5 &&
                                b.y + b.height <= c.height - inset + 0.5,
        dark: dark(b.x, b.y, b.x + b.width, b.y + b.height),
        at: [b.x, b.y, b.width, b.height].map(Math.round).join(',') }));
      // (right of the world's edge line, 2 pixels wide, to the canvas's edge)
      const edge = A.worldToCanvas(5, 0)[0];
      return { boxes, width: c.width, height: c.height, drawn: A.drawn().labels,
               rightOfWorld: A.view().zoom > 1 ? 0 : dark(edge + 2, 0, c.width, c.height) };
    });
    const describe = l => l.boxes.map(b => b.robot + ':' + b.at + (b.inside ? '' : ' OUT') + ' dark ' + b.dark).join('; ') +
                          ' in ' + l.width + 'x' + l.height;
    const whole = await labels();
    check(whole.boxes.length === 4 && whole.drawn === 4, 'the whole world\'s view draws the 4 labels (' + whole.boxes.length + ' boxes)');
    check(whole.boxes.every(b => b.inside), 'each label lies within the canvas (' + describe(whole) + ')');
    check(whole.boxes.every(b => b.dark >= 10), 'each label is drawn in its box (' + describe(whole) + ')');
    check(whole.rightOfWorld === 0, 'nothing dark right of the world\'s edge (' + whole.rightOfWorld + ' pixels)');
    // zoomed in on the top right quarter, which clips to the world's rectangle
    await R(() => window.afrpReplay.setView(2, 2.5, 2.5));
    const zoomed = await labels();
    const inView = zoomed.boxes.map(b => b.robot).sort().join(',');
    check(inView === '0,1,2', 'zoomed in on the top right quarter, A1, B1 and A22 are labelled (robots ' + inView + ')');
    check(zoomed.boxes.every(b => b.inside && b.dark >= 10),
          'each label lies within the world\'s rectangle and is drawn there (' + describe(zoomed) + ')');
    await R(() => window.afrpReplay.setView(1, 0, 0));

    // Where a text's lines break inside a word: the characters either side
    // of each break that are both letters or digits (lines that a newline
    // ends are not breaks).
    const midWord = id => R(id => {
      const el = document.getElementById(id), out = [];
      const walker = document.createTreeWalker(el, NodeFilter.SHOW_TEXT), range = document.createRange();
      for (let node; (node = walker.nextNode());) {
        const text = node.textContent;
        let lastTop = null;
        for (let i = 0; i < text.length; i++) {
          if (text[i] === '\n') { lastTop = null; continue; }
          range.setStart(node, i); range.setEnd(node, i + 1);
          const rects = range.getClientRects();
          if (rects.length === 0) continue;
          const top = rects[rects.length - 1].top;
          if (lastTop !== null && top > lastTop + 2 && /\w/.test(text[i - 1]) && /\w/.test(text[i]))
            out.push(text.slice(Math.max(0, i - 8), i) + '|' + text.slice(i, i + 8));
          lastTop = top;
        }
      }
      return out;
    }, id);
    const broken = [];
    for (let width = 320; width <= 1400; width += 20) {
      await page.setViewportSize({ width, height: 800 });
      for (const id of ['info', 'meta']) (await midWord(id)).forEach(b => broken.push(width + ' px, #' + id + ': ' + JSON.stringify(b)));
    }
    check(broken.length === 0, 'the help text and the summary line break between words at 320 to 1400 pixels' +
          (broken.length ? ' (inside one: ' + broken.slice(0, 6).join('; ') + (broken.length > 6 ? '; ...' : '') + ')' : ''));

    // The play button's width and the places of the controls after it, as
    // Play, as Pause (pressed) and as Play again (pressed again).
    for (const width of [1200, 600]) {
      await page.setViewportSize({ width, height: 800 });
      const press = () => R(() => {
        const boxes = ['play', 'fwd', 'slider', 'speed'].map(id => {
          const r = document.getElementById(id).getBoundingClientRect();
          return id + ' ' + r.left.toFixed(1) + '+' + r.width.toFixed(1) + '@' + r.top.toFixed(1);
        }).join(', ');
        const label = document.getElementById('play').textContent;
        document.getElementById('play').click();
        return { label, boxes };
      });
      const shown = [await press(), await press(), await press()];
      check(shown.map(s => s.label).join(',') === 'Play,Pause,Play' &&
            shown.every(s => s.boxes === shown[0].boxes),
            'at ' + width + ' px the controls stay in place as Play becomes Pause and back (' +
            shown.map(s => s.label + ': ' + s.boxes).join(' | ') + ')');
      await R(() => window.afrpReplay.pause());
    }

    const title = await page.title();
    check(title === 'simbot, world a\\b.world - afrp replay', 'the title names the world file a\\b.world (' + JSON.stringify(title) + ')');
    check(opened.frame === 0 && opened.falsified === -1 && opened.list === null,
          'no property decided false: the page opens at frame 0, no mark on the slider (' + JSON.stringify(opened) + ')');
    check(errors.length === 0, 'no console errors' + (errors.length ? ': ' + errors.join('; ') : ''));
});
