// The afrp replay page: draws the run log embedded in #afrp-log (and, for
// a long log, the elements #afrp-log-2, #afrp-log-3, ... that continue it)
// on a canvas. Every string that comes from the run is shown with
// textContent, never parsed as HTML.
(function () {
  'use strict';
  // the log's lines: #afrp-log's array, then those of #afrp-log-2, ...
  function readLog() {
    var all = JSON.parse(document.getElementById('afrp-log').textContent);
    for (var k = 2, el; (el = document.getElementById('afrp-log-' + k)); k++) {
      var part = JSON.parse(el.textContent);
      for (var i = 0; i < part.length; i++) all.push(part[i]);
    }
    return all;
  }
  var lines = readLog();
  var header = lines[0];
  // The run, for the page's title (a tab among others) and its heading:
  // its program (and the example, for afrp-examples NAME) and its world
  // file, from its command line, e.g. "simbot, world maze.world - afrp
  // replay". (A path's folders end at '/' alone, as on the systems simbot
  // runs on: a world file named a\b.world was titled b.world.)
  function runName() {
    var cl = header.commandLine || [], base = function (p) { return String(p).split('/').pop(); };
    if (cl.length === 0) return '';
    // (the last --world, as the command line's parser takes the last)
    var name = base(cl[0]), w = cl.lastIndexOf('--world');
    if (cl.length > 1 && cl[1] !== '' && cl[1].charAt(0) !== '-') name += ' ' + cl[1];
    if (w > 0 && w + 1 < cl.length) name += ', world ' + base(cl[w + 1]);
    return name;
  }
  var run = runName();
  document.title = (run ? run + ' - ' : '') + 'afrp replay';
  var frames = lines.filter(function (l) { return l.kind === 'frame'; });
  var summary = lines.filter(function (l) { return l.kind === 'summary'; })[0] || null;
  // A test's property of the run decided false (afrp-test's forAllRuns
  // writes it): the instant that decided, 't', and a line that says so,
  // 'text'. The page says the line in its heading and its summary, and
  // opens at that instant, marked on the slider (it opened at frame 0,
  // the instant only in the test's output).
  var falsified = (summary && summary.falsified) || null;
  // The run's failure (a controller's or the referee's, a write's), as the
  // heading says it: its first line, at most 200 characters (the summary
  // line below has it whole). A failed run's heading said nothing of it.
  var failed = null;
  if (summary && summary.failure) {
    failed = summary.failure.split('\n')[0];
    if (failed.length > 200) failed = failed.slice(0, 199) + '\u2026';
  }
  // (the heading, as text, said "afrp replay" on every page)
  document.getElementsByTagName('h1')[0].textContent = 'afrp replay' + (run ? ': ' + run : '') +
    (failed !== null ? ' - FAILED: ' + failed : '') + (falsified ? ' - FAILED: ' + falsified.text : '');
  if (frames.length === 0) {
    document.getElementById('meta').textContent = 'This log has no frames: the run stopped before its first.';
    window.afrpReplay = { header: header, summary: summary, frameCount: function () { return 0; } };
    return;
  }
  var canvas = document.getElementById('world');
  var ctx = canvas.getContext('2d');
  var $ = function (id) { return document.getElementById(id); };
  var b = header.bounds;
  var x0 = b.x - b.width / 2, y1 = b.y + b.height / 2;
  // The canvas has 'dpr' pixels a CSS pixel, the screen's (its
  // devicePixelRatio: 2 on many laptops and phones, where a canvas of CSS
  // pixels was drawn blurred), at most 2 (the trails' copies below take
  // dpr^2 times the memory) and at least 1, and is shown at its size in
  // CSS pixels; the sizes drawn, in CSS pixels, are times dpr. The
  // browser's zoom, or the window taken to another screen, changes the
  // ratio: the canvas is then given the new ratio's pixels (see rescale
  // below; it kept those of the ratio the page opened with, blurred after
  // a zoom in).
  var dpr, margin, fitScale;
  function setPixels() {
    dpr = clamp(window.devicePixelRatio || 1, 1, 2);
    margin = 10 * dpr;
    // pixels a metre with the whole world in view (620 CSS pixels on its long side)
    fitScale = Math.min(620 / b.width, 620 / b.height) * dpr;
    canvas.width = Math.round(b.width * fitScale + 2 * margin);
    canvas.height = Math.round(b.height * fitScale + 2 * margin);
    // (its border added: the style's box-sizing is border-box)
    canvas.style.width = canvas.width / dpr + canvas.offsetWidth - canvas.clientWidth + 'px';
  }
  setPixels();

  // The view: the world point at the middle of the world's rectangle on
  // the canvas, and a zoom (1: the whole world; up to 250 pixels a metre,
  // or 1 if the whole world is already that close). Zoomed in, the view
  // stays within the world. 'scale' is the view's pixels a metre; 'vx0'
  // and 'vy1' the world's coordinates at the rectangle's top left corner.
  // (the same at every ratio: fitScale is times dpr too)
  var maxZoom = Math.max(1, 250 * dpr / fitScale);
  var view = { zoom: 1, cx: b.x, cy: b.y };
  var scale, vx0, vy1, fine, viewKey;
  function clamp(v, lo, hi) { return Math.max(lo, Math.min(hi, v)); }
  // a count and its noun, singular for 1 ('1 robot', '2 robots')
  function counted(n, noun) { return n + ' ' + noun + (n === 1 ? '' : 's'); }
  function setView(zoom, cx, cy) {
    var z = clamp(zoom, 1, maxZoom), hw = b.width / 2 / z, hh = b.height / 2 / z;
    view = { zoom: z, cx: clamp(cx, x0 + hw, x0 + b.width - hw), cy: clamp(cy, y1 - b.height + hh, y1 - hh) };
    scale = fitScale * z;
    vx0 = view.cx - hw; vy1 = view.cy + hh;
    // In a big world a robot is a few pixels across: its rim, heading mark and
    // id shrink with it (full size from 30 px/m up, the notes' world included).
    fine = Math.min(1, scale / 30 / dpr);
    viewKey = view.zoom + ' ' + view.cx + ' ' + view.cy;
    // On a touch screen the whole world's view leaves a finger's vertical
    // swipe to the page, which scrolls (there is nothing to move: the view
    // is the world); a zoomed view takes every touch, to move it.
    canvas.style.touchAction = z > 1 ? 'none' : 'pan-y';
  }
  setView(1, b.x, b.y);
  // the view of zoom z (within its limits) with world point w at canvas point (px, py)
  function placeAt(w, px, py, z) {
    z = clamp(z, 1, maxZoom);
    var s = fitScale * z;
    setView(z, w[0] - (px - margin) / s + b.width / 2 / z, w[1] + (py - margin) / s - b.height / 2 / z);
  }
  // zoom by a factor, keeping the world point under canvas point (px, py) there
  function zoomAt(px, py, factor) { placeAt(toWorld(px, py), px, py, view.zoom * factor); }

  var state = { frame: 0, playing: false, selected: -1, speed: 1, simTime: 0, last: null };

  function toCanvas(x, y) { return [margin + (x - vx0) * scale, margin + (vy1 - y) * scale]; }
  function toWorld(px, py) { return [vx0 + (px - margin) / scale, vy1 - (py - margin) / scale]; }
  // whether a canvas point is within d pixels of the canvas
  function nearCanvas(p, d) { return p[0] > -d && p[1] > -d && p[0] < canvas.width + d && p[1] < canvas.height + d; }
  function rgb(c) { return 'rgb(' + c[0] + ',' + c[1] + ',' + c[2] + ')'; }
  function darken(f, c) { return [Math.round(c[0] * f), Math.round(c[1] * f), Math.round(c[2] * f)]; }
  function blend(f, a, c) { return [0, 1, 2].map(function (i) { return Math.round(f * a[i] + (1 - f) * c[i]); }); }
  var background = [240, 240, 230];
  function typeColour(t) { return t === 'SimbotA' ? [30, 90, 220] : t === 'SimbotB' ? [215, 40, 40] : [140, 60, 170]; }
  var shades = {
    SimbotA: [[0, 150, 200], [90, 50, 200], [20, 50, 130], [110, 170, 255], [0, 110, 140]],
    SimbotB: [[230, 90, 170], [150, 20, 90], [120, 20, 20], [245, 130, 110], [170, 90, 60]],
    other: [[190, 90, 210], [100, 30, 130], [210, 140, 230], [120, 60, 100], [160, 40, 120]]
  };
  // the k-th robot of its type (from 0) has the type's colour, the others a shade
  var ranks = {}, colours = header.robots.map(function (r) {
    var k = ranks[r.type] || 0; ranks[r.type] = k + 1;
    if (k === 0) return typeColour(r.type);
    var s = shades[r.type] || shades.other;
    return s[(k - 1) % s.length];
  });
  // The id drawn beside each robot: its id, or, when robots of two types
  // share an id (SimbotA 1 and SimbotB 1), its type's letter and its id
  // (A1, B1) for every robot, so that no two labels are the same.
  var typesOfId = {};
  header.robots.forEach(function (r) {
    var ts = typesOfId[r.id] || (typesOfId[r.id] = []);
    if (ts.indexOf(r.type) < 0) ts.push(r.type);
  });
  var idsShared = Object.keys(typesOfId).some(function (k) { return typesOfId[k].length > 1; });
  var robotLabels = header.robots.map(function (r) {
    return idsShared ? String(r.type).replace(/^Simbot/, '') + r.id : String(r.id);
  });

  // A layer: a canvas of the page's canvas's size, not in the page.
  function layer() {
    var c = document.createElement('canvas');
    c.width = canvas.width; c.height = canvas.height;
    return { canvas: c, ctx: c.getContext('2d'), view: null, upTo: -1 };
  }
  // Zoomed in, what is drawn stays within the world's rectangle.
  function clipToWorld(g) {
    if (view.zoom > 1) { g.beginPath(); g.rect(margin, margin, b.width * fitScale, b.height * fitScale); g.clip(); }
  }

  // What does not move (the floor, the world's edge, goals, walls and
  // blocks), drawn once for each view.
  var still = layer();
  function drawStill() {
    if (still.view !== viewKey) {
      var g = still.ctx;
      g.save();
      g.fillStyle = rgb(background); g.fillRect(0, 0, canvas.width, canvas.height);
      clipToWorld(g);
      var c0 = toCanvas(x0, y1);
      g.lineWidth = 2 * dpr; g.strokeStyle = 'rgb(45,45,45)';
      g.strokeRect(c0[0], c0[1], b.width * scale, b.height * scale);
      // (walls and blocks at least a pixel wide and tall, about their
      // centre, so that a big world's thin walls still show, as its
      // robots do)
      var rect = function (r, fill, least) {
        var w = Math.max(r.width * scale, least), h = Math.max(r.height * scale, least);
        var c = toCanvas(r.x, r.y);
        g.fillStyle = fill;
        g.fillRect(c[0] - w / 2, c[1] - h / 2, w, h);
      };
      header.goals.forEach(function (k) { rect(k, 'rgba(60,170,60,0.25)', 0); });
      header.walls.forEach(function (w) { rect(w, 'rgb(90,90,90)', dpr); });
      header.blocks.forEach(function (k) { rect(k, 'rgb(139,90,43)', dpr); });
      g.restore();
      still.view = viewKey;
    }
    ctx.drawImage(still.canvas, 0, 0);
  }

  // The trails, on a layer of their own that keeps the paths up to the
  // frame they were last drawn for, in the view they were drawn in: going
  // forward adds only the new stretch of each path (playing a big world's
  // page draws a few segments a robot per frame, not its whole path
  // again); going back starts from a copy kept earlier (below), and
  // another view draws the paths afresh. (Drawn
  // whole at every frame, the trails of 1000 robots took 0.4 s a frame
  // near the end of a 30 s page.)
  var trails = layer();
  // A copy of the layer is kept at every keepEvery-th frame it passes
  // (every 25th, or every sixteenth of the frames on a longer page: at
  // most 16 copies for a view, 1.6 MB each at the largest canvas, 6.6 MB
  // at a dpr of 2), so that going back, a jump or the slider dragged
  // backwards draws the paths from the nearest copy before the frame, not
  // from the start (a 1000-robot, 30 s page: 0.2-0.6 s from the start).
  var keepEvery = Math.max(25, Math.ceil(frames.length / 16));
  trails.saved = [];
  // While the wheel, a drag or a pinch changes the view, redrawing the
  // paths of a big page at every step (1000 robots for 30 s: about 0.2 s;
  // 10,000 robots: about 1 s) would make the view lag: when the layer holds more
  // than 'roughAbove' stretches, the view's changes show the layer as it
  // is, moved and scaled to the new view (rough), and the paths are drawn
  // afresh 0.25 s after the last change.
  var trailsRough = false;
  function drawTrails(upTo, quick) {
    var g = trails.ctx;
    trailsRough = quick && trails.view !== viewKey && trails.upTo === upTo && trails.at &&
                  header.robots.length * upTo > api.roughAbove;
    if (trailsRough) {
      var k = scale / trails.at.scale;
      ctx.save();
      ctx.setTransform(k, 0, 0, k, margin * (1 - k) + (trails.at.vx0 - vx0) * scale,
                       margin * (1 - k) + (vy1 - trails.at.vy1) * scale);
      ctx.drawImage(trails.canvas, 0, 0);
      ctx.restore();
      return;
    }
    if (trails.view !== viewKey) {
      g.clearRect(0, 0, canvas.width, canvas.height); trails.upTo = -1; trails.saved = [];
      trails.view = viewKey; trails.at = { scale: scale, vx0: vx0, vy1: vy1 };
    }
    if (upTo < trails.upTo) {
      // back: from the copy kept last at or before the frame, or from nothing
      var kept = null;
      trails.saved.forEach(function (c) { if (c.upTo <= upTo) kept = c; });
      g.clearRect(0, 0, canvas.width, canvas.height); trails.upTo = -1;
      if (kept) { g.drawImage(kept.canvas, 0, 0); trails.upTo = kept.upTo; }
    }
    while (upTo > trails.upTo) {
      // the stretches up to the frame, or to the next multiple of keepEvery
      var from = Math.max(trails.upTo, 0);
      var to = Math.min(upTo, (Math.floor(from / keepEvery) + 1) * keepEvery);
      g.save(); clipToWorld(g);
      header.robots.forEach(function (r, i) {
        g.beginPath();
        for (var j = from; j <= to; j++) {
          var p = toCanvas(frames[j].robots[i].x, frames[j].robots[i].y);
          if (j === from) g.moveTo(p[0], p[1]); else g.lineTo(p[0], p[1]);
        }
        g.lineWidth = dpr; g.strokeStyle = rgb(blend(0.5, typeColour(r.type), background)); g.stroke();
      });
      g.restore();
      trails.upTo = to;
      if (to % keepEvery === 0 && !trails.saved.some(function (c) { return c.upTo === to; })) {
        var copy = layer();
        copy.ctx.drawImage(trails.canvas, 0, 0);
        trails.saved.push({ upTo: to, canvas: copy.canvas });
        trails.saved.sort(function (x, y) { return x.upTo - y.upTo; });
      }
    }
    ctx.drawImage(trails.canvas, 0, 0);
  }

  // The robots, each drawn where the log puts it: a disc in its colour
  // (darker when its bumper is pressed; at least 1.5 pixels in radius, so
  // that a big world's robots stay visible), a rim and a white heading
  // mark (unless under half a pixel wide, or under 1.5 pixels long), and
  // its id when it can be read: when the robot is at least 8 pixels
  // across, or at most 200 robots are in view (and always the selected
  // robot's). Robots with the same colours are drawn as one path (10,000
  // robots drawn one by one took about 0.2 s a frame); so are the rays,
  // the heading marks and the balls. Robots out of view are skipped.
  // (These pixels, and the lines' widths, are CSS pixels: times dpr.)
  var drawn = { robots: 0, labels: 0, labelBoxes: [] };
  function drawMoving(f) {
    var balls = new Path2D(), ballRadius = header.ballRadius * scale;
    f.balls.forEach(function (p) {
      var c = toCanvas(p[0], p[1]);
      if (nearCanvas(c, ballRadius + 2 * dpr)) { balls.moveTo(c[0] + ballRadius, c[1]); balls.arc(c[0], c[1], ballRadius, 0, 2 * Math.PI); }
    });
    ctx.fillStyle = 'rgb(255,140,0)'; ctx.fill(balls);
    ctx.lineWidth = 1.5 * fine * dpr; ctx.strokeStyle = 'rgb(170,90,0)'; ctx.stroke(balls);

    var reach = 5 * scale;   // (a ray or a sighting is shorter than 5 m)
    var rays = $('rays').checked ? new Path2D() : null;
    var seen = $('sightings').checked ? { robots: new Path2D(), balls: new Path2D() } : null;
    var groups = new Map(), marks = new Path2D(), labels = [];
    f.robots.forEach(function (r, i) {
      var here = toCanvas(r.x, r.y);
      if (!nearCanvas(here, reach)) return;
      var info = header.robots[i], radius = info.radius * scale;
      // a line in direction a (relative to the heading) from `from` to
      // `to` metres off the robot's centre
      var ray = function (path, a, from, to) {
        var c = Math.cos(r.heading + a), s = Math.sin(r.heading + a);
        var start = toCanvas(r.x + from * c, r.y + from * s), end = toCanvas(r.x + to * c, r.y + to * s);
        path.moveTo(start[0], start[1]); path.lineTo(end[0], end[1]);
      };
      // (a range reading is measured from the robot's edge; a sighting's
      // distance is between centres)
      if (rays) header.rangeAngles.forEach(function (a, k) {
        if (r.range[k] !== null) ray(rays, a, info.radius, info.radius + r.range[k]);
      });
      if (seen) {
        r.seenRobots.forEach(function (s) { ray(seen.robots, s[2], 0, s[3]); });
        r.seenBalls.forEach(function (s) { ray(seen.balls, s[0], 0, s[1]); });
      }
      if (!nearCanvas(here, radius + 40 * dpr)) return;
      var col = colours[i], selected = i === state.selected;
      var fill = rgb(r.bumper ? darken(0.6, col) : col), rim = r.bumper ? 'rgb(0,0,0)' : rgb(darken(0.5, col));
      var width = (selected ? Math.max(2, 4 * fine) : 2 * fine) * dpr, key = fill + rim + width;
      var group = groups.get(key);
      if (!group) { group = { fill: fill, rim: rim, width: width, path: new Path2D() }; groups.set(key, group); }
      var shown = Math.max(radius, 1.5 * dpr);
      group.path.moveTo(here[0] + shown, here[1]); group.path.arc(here[0], here[1], shown, 0, 2 * Math.PI);
      if (radius >= 1.5 * dpr) {
        marks.moveTo(here[0], here[1]);
        marks.lineTo(here[0] + radius * Math.cos(r.heading), here[1] - radius * Math.sin(r.heading));
      }
      labels.push([i, here, radius]);
    });
    if (rays) { ctx.lineWidth = dpr; ctx.strokeStyle = 'rgb(0,170,60)'; ctx.stroke(rays); }
    if (seen) {
      ctx.setLineDash([4 * dpr, 3 * dpr]); ctx.lineWidth = dpr;
      ctx.strokeStyle = 'rgba(120,40,160,0.8)'; ctx.stroke(seen.robots);
      ctx.strokeStyle = 'rgba(200,110,0,0.8)'; ctx.stroke(seen.balls);
      ctx.setLineDash([]);
    }
    groups.forEach(function (g) {
      ctx.fillStyle = g.fill; ctx.fill(g.path);
      if (g.width >= 0.5 * dpr) { ctx.lineWidth = g.width; ctx.strokeStyle = g.rim; ctx.stroke(g.path); }
    });
    ctx.lineWidth = 3 * fine * dpr; ctx.strokeStyle = 'rgb(255,255,255)'; ctx.stroke(marks);
    var crowd = labels.length > 200, size = Math.round(Math.max(8, 12 * fine) * dpr);
    ctx.fillStyle = 'rgb(20,20,20)'; ctx.font = size + 'px sans-serif';
    drawn = { robots: labels.length, labels: 0, labelBoxes: [] };
    // A label goes above the robot's disc, on its right; on its left when
    // it would leave the canvas on the right, and below the disc when it
    // would leave it at the top (zoomed in, the world's rectangle, which
    // clips what is drawn): the labels of robots at the world's right or
    // top edge were cut off ("A2" showed as "A").
    var inset = view.zoom > 1 ? margin : 0;
    labels.forEach(function (l) {
      if (!crowd || l[2] >= 4 * dpr || l[0] === state.selected) {
        var text = robotLabels[l[0]], m = ctx.measureText(text), gap = l[2] + 2 * dpr;
        var ascent = m.actualBoundingBoxAscent || 0.8 * size, descent = m.actualBoundingBoxDescent || 0;
        var x = l[1][0] + gap, y = l[1][1] - l[2];
        if (x + m.width > canvas.width - inset) x = l[1][0] - gap - m.width;
        if (y - ascent < inset) y = l[1][1] + l[2] + ascent;
        ctx.fillText(text, x, y);
        drawn.labels++;
        drawn.labelBoxes.push({ robot: l[0], x: x, y: y - ascent, width: m.width, height: ascent + descent });
      }
    });
  }

  function draw(quick) {
    var f = frames[state.frame];
    drawStill();
    ctx.save(); clipToWorld(ctx);
    trailsRough = false;
    if ($('trails').checked) drawTrails(state.frame, quick);
    drawMoving(f);
    ctx.restore();
    // (the program's scores, if it keeps any, after the time: "score: A 1, B 0")
    var scoreNames = f.scores ? Object.keys(f.scores) : [];
    $('time').textContent = 't = ' + f.t.toFixed(2) + ' s  (frame ' + state.frame + ' of ' + (frames.length - 1) + ')' +
      (scoreNames.length ? '  score: ' + scoreNames.map(function (k) { return k + ' ' + f.scores[k]; }).join(', ') : '');
    $('slider').value = String(state.frame);
    $('play').textContent = state.playing ? playLabels.playing : playLabels.paused;
    showInfo();
    showEvents();
  }
  // With "follow" ticked and a robot selected, a zoomed view keeps the
  // robot in its middle part: when the robot leaves the middle 60% of the
  // view, the view is centred on it again (in jumps, not at every frame,
  // so that the trails are drawn afresh only then), as the frame changes
  // (a drag or the wheel can take the view elsewhere meanwhile).
  function follow(f) {
    if (!$('follow').checked || state.selected < 0 || view.zoom <= 1) return;
    var r = f.robots[state.selected], p = toCanvas(r.x, r.y);
    var w = b.width * fitScale, h = b.height * fitScale;
    if (Math.abs(p[0] - margin - w / 2) > 0.3 * w || Math.abs(p[1] - margin - h / 2) > 0.3 * h) setView(view.zoom, r.x, r.y);
  }
  // a view changed by the wheel, a drag or a pinch: drawn once at the next
  // animation frame (the trails maybe rough), and in full 0.25 s after the
  // last change
  var drawPending = false, fullTimer = null;
  function drawSoon() {
    if (!drawPending) { drawPending = true; requestAnimationFrame(function () { drawPending = false; draw(true); }); }
    clearTimeout(fullTimer);
    fullTimer = setTimeout(function () { fullTimer = null; if (trailsRough) draw(); }, 250);
  }

  // The screen's ratio changed (the browser's zoom, another screen): the
  // canvas and its layers get the new ratio's pixels, the view (its zoom
  // and middle) and the frame are kept, and all is drawn afresh; the
  // trails' copies, of the old size, go. Looked at on every resize of the
  // window (a zoom resizes the page's CSS pixels too) and when the
  // resolution the page was drawn for stops matching.
  function rescale() {
    if (clamp(window.devicePixelRatio || 1, 1, 2) === dpr) return;
    setPixels();
    [still, trails].forEach(function (l) {
      l.canvas.width = canvas.width; l.canvas.height = canvas.height; l.view = null; l.upTo = -1;
    });
    trails.saved = []; trails.at = null;
    setView(view.zoom, view.cx, view.cy);
    // (a gesture under way goes on from the view as it is, in the new pixels)
    Object.keys(pointers).forEach(function (k) { pointers[k].at = pixelAt(pointers[k].client[0], pointers[k].client[1]); });
    startGesture();
    draw();
  }
  function watchRatio() {
    if (!window.matchMedia) return;
    var query = window.matchMedia('(resolution: ' + (window.devicePixelRatio || 1) + 'dppx)');
    var changed = function () {
      if (query.removeEventListener) query.removeEventListener('change', changed); else query.removeListener(changed);
      rescale();
      watchRatio();
    };
    if (query.addEventListener) query.addEventListener('change', changed); else query.addListener(changed);
  }

  function num(x, d) { return x === null ? 'n/a' : x.toFixed(d == null ? 3 : d); }
  function showInfo() {
    var el = $('info');
    if (state.selected < 0) {
      infoShownFor = -1;
      el.textContent = 'Click or tap a robot to see its readings.\n' +
        'Zoom with the wheel, two fingers or + and -; drag to move; 0 or Fit for the whole world.';
      return;
    }
    var i = state.selected, info = header.robots[i], r = frames[state.frame].robots[i];
    var out = [];
    out.push(info.type + ' ' + info.id + (idsShared ? ' (drawn ' + robotLabels[i] + ')' : '') +
             '   at t = ' + frames[state.frame].t.toFixed(2) + ' s');
    out.push('position  (' + num(r.x) + ', ' + num(r.y) + ') m   heading ' + num(r.heading) + ' rad');
    out.push('wheels    left ' + num(r.wheels[0]) + '  right ' + num(r.wheels[1]) + ' m/s');
    out.push('velocity  v ' + num(r.v) + ' m/s   omega ' + num(r.omega) + ' rad/s');
    out.push('bumper    ' + (r.bumper ? 'STUCK' : 'free'));
    out.push('battery   ' + r.battery + ' (' + num(r.charge * 100, 1) + ' %)');
    out.push('odometry  (' + num(r.odometry[0]) + ', ' + num(r.odometry[1]) + ')');
    var names = ['front', 'left', 'back', 'right'];
    out.push('range     ' + header.rangeAngles.map(function (a, k) {
      return (names[k] || num(a, 2)) + ' ' + num(r.range[k], 2);
    }).join('  ') + ' m');
    out.push('tracker   ' + (r.seenRobots.length + r.seenBalls.length === 0 ? 'nothing' : ''));
    r.seenRobots.forEach(function (s) {
      out.push('  ' + s[0] + ' ' + s[1] + ' at ' + num(s[2], 2) + ' rad, ' + num(s[3], 2) + ' m');
    });
    r.seenBalls.forEach(function (s) { out.push('  ball at ' + num(s[0], 2) + ' rad, ' + num(s[1], 2) + ' m'); });
    // The robot's last 50 messages up to the frame, newest first, from the
    // index the events panel's lines are made with (they were gathered
    // from frame 0 at every frame drawn). Newest first, the newest is the
    // line below the readings, read with them as the robot's latest word,
    // at the same place while playing; its older ones follow, to be
    // scrolled to. (Newest last, it was below the panel's bottom once the
    // lines outgrew it, soon on a narrow window, which wraps the readings;
    // the panel scrolled to its end would hide the readings instead.)
    indexEvents(state.frame);
    var said = robotMessages[i] || { frames: [], lines: [] }, n = messagesUpTo(said, state.frame);
    out.push('messages (up to now, newest first):');
    var msgs = said.lines.slice(Math.max(0, n - 50), n).reverse();
    if (msgs.length === 0) msgs.push('  none');
    el.textContent = out.concat(msgs).join('\n');
    // (another robot's readings are shown from the top)
    if (i !== infoShownFor) { el.scrollTop = 0; infoShownFor = i; }
  }
  var infoShownFor = -1;
  // The events panel's lines in the run's order: each frame's events (a
  // bump, a score) and its robots' messages, by time, then the console
  // lines no robot printed; 'eventsUpTo[j]', how many of them frames 0 to
  // j have. Made as far as the frames shown so far reach (a page's first
  // frame does not wait for them: the robots' messages are looked for in
  // every robot-frame, about 0.4 microseconds each, some 0.5 s for the
  // largest page). (The messages were only in the selected robot's panel;
  // and the lines were gathered from frame 0 at every frame drawn.)
  // Each robot's messages are kept too, for its panel: 'robotMessages[i]'
  // (for a robot that has printed) has their lines and the frame of each,
  // and 'messagesUpTo' counts those of frames 0 to j.
  var eventLines = [], eventsUpTo = [], robotMessages = {};
  function indexEvents(upTo) {
    for (var j = eventsUpTo.length; j <= upTo; j++) {
      var f = frames[j], own = [];
      f.events.forEach(function (e) { own.push([e.t, '[' + e.t.toFixed(2) + '] ' + e.kind + ': ' + e.text]); });
      for (var i = 0; i < f.robots.length; i++) {
        var ms = f.robots[i].messages;
        if (ms.length > 0 && !(i in robotMessages)) robotMessages[i] = { frames: [], lines: [] };
        for (var k = 0; k < ms.length; k++) {
          own.push([ms[k][0], '[' + ms[k][0].toFixed(2) + '] ' + header.robots[i].type + ' ' + header.robots[i].id + ': ' + ms[k][1]]);
          robotMessages[i].frames.push(j);
          robotMessages[i].lines.push('  [' + ms[k][0].toFixed(2) + '] ' + ms[k][1]);
        }
      }
      // (Array.prototype.sort is stable: a step's events, then its messages)
      own.sort(function (x, y) { return x[0] - y[0]; });
      own.forEach(function (l) { eventLines.push(l[1]); });
      f.console.forEach(function (c) { eventLines.push(c); });
      eventsUpTo.push(eventLines.length);
    }
  }
  // (a binary search: the first of the robot's messages after frame j)
  function messagesUpTo(said, j) {
    var lo = 0, hi = said.frames.length;
    while (lo < hi) { var mid = (lo + hi) >> 1; if (said.frames[mid] <= j) lo = mid + 1; else hi = mid; }
    return lo;
  }
  // The last 30 lines up to the frame, newest last (as a log is read; the
  // robot's panel, whose readings come first, has its messages newest
  // first), scrolled to the end so that the newest shows, also
  // after a step back; the panel is left as it is (and where the user
  // scrolled it) while the frame brings no line and takes none away.
  var eventsShown = -1;
  function showEvents() {
    indexEvents(state.frame);
    var n = eventsUpTo[state.frame], el = $('events');
    if (n === eventsShown) return;
    eventsShown = n;
    el.textContent = eventLines.slice(Math.max(0, n - 30), n).join('\n');
    el.scrollTop = el.scrollHeight;
  }

  function setFrame(i) {
    state.frame = Math.max(0, Math.min(frames.length - 1, Math.round(i)));
    state.simTime = frames[state.frame].t;
    follow(frames[state.frame]);
    draw();
  }
  function setPlaying(p) {
    state.playing = p && frames.length > 1;
    if (state.playing && state.frame >= frames.length - 1) setFrame(0);
    state.last = null;
    draw();
    if (state.playing) requestAnimationFrame(tick);
  }
  // (while the slider is held, playing leaves the frame to it, and takes
  // no time: once it is let go, playing goes on from the frame it was left
  // at; the playhead and the hand used to pull the slider each their way)
  var sliderHeld = false;
  function tick(now) {
    if (!state.playing) return;
    if (state.last !== null && !sliderHeld) {
      state.simTime += (now - state.last) / 1000 * state.speed;
      var i = state.frame;
      while (i + 1 < frames.length && frames[i + 1].t <= state.simTime) i++;
      if (i !== state.frame) { state.frame = i; follow(frames[i]); draw(); }
      if (i >= frames.length - 1) { state.playing = false; draw(); return; }
    }
    state.last = now;
    requestAnimationFrame(tick);
  }
  // the robot whose disc is within reach (canvas pixels) of a canvas
  // pixel, the nearest (by its centre) if several are: -1 if none
  function robotAt(px, py, reach) {
    var f = frames[state.frame], best = -1, bestD = Infinity;
    f.robots.forEach(function (r, i) {
      var p = toCanvas(r.x, r.y), d = Math.hypot(p[0] - px, p[1] - py);
      if (d <= Math.max(header.robots[i].radius * scale, 1.5 * dpr) + reach && d < bestD) { best = i; bestD = d; }
    });
    return best;
  }

  // The play button as wide as its wider label ("Pause"), so that the
  // controls after it stay where they are when it changes (they moved by
  // the labels' difference at every press of Play and Pause)
  var playLabels = { playing: 'Pause', paused: 'Play' };
  (function () {
    var button = $('play'), widest = 0;
    [playLabels.playing, playLabels.paused].forEach(function (label) {
      button.textContent = label;
      widest = Math.max(widest, button.getBoundingClientRect().width);
    });
    button.style.minWidth = widest + 'px';
  })();

  $('slider').max = String(frames.length - 1);
  // the frame nearest the instant that decided a property false (the
  // later of two as near), marked on the slider: -1 if none
  var falsifiedFrame = -1;
  if (falsified) {
    falsifiedFrame = 0;
    frames.forEach(function (f, i) {
      if (Math.abs(f.t - falsified.t) <= Math.abs(frames[falsifiedFrame].t - falsified.t)) falsifiedFrame = i;
    });
    var marks = document.createElement('datalist'), mark = document.createElement('option');
    marks.id = 'slider-marks';
    mark.value = String(falsifiedFrame); mark.label = 'decided false';
    marks.appendChild(mark);
    document.body.appendChild(marks);
    $('slider').setAttribute('list', marks.id);
    $('slider').title = 'the mark: t = ' + frames[falsifiedFrame].t.toFixed(2) + ' s, where the property was decided false';
  }
  $('slider').addEventListener('input', function () { setFrame(Number($('slider').value)); });
  $('slider').addEventListener('pointerdown', function () { sliderHeld = true; });
  // (let go anywhere, or the window left in the middle of the drag)
  ['pointerup', 'pointercancel'].forEach(function (type) {
    document.addEventListener(type, function () { sliderHeld = false; });
  });
  window.addEventListener('blur', function () { sliderHeld = false; });
  $('play').addEventListener('click', function () { setPlaying(!state.playing); });
  $('back').addEventListener('click', function () { setPlaying(false); setFrame(state.frame - 1); });
  $('fwd').addEventListener('click', function () { setPlaying(false); setFrame(state.frame + 1); });
  // (the list gives the focus back once a speed is chosen: the keys, which
  // a focused list takes for itself, went on working only after a click
  // elsewhere)
  $('speed').addEventListener('change', function () { state.speed = Number($('speed').value); $('speed').blur(); });
  // Faster than the page's list: 8x to 32x (at 32x a 6-minute run plays in
  // 11 s). Playing goes by the clock, so the frames that a screen's
  // refresh cannot show at such a speed are passed over, and the time
  // still runs at the speed chosen.
  [8, 16, 32].forEach(function (v) {
    var sel = $('speed');
    if (Array.prototype.some.call(sel.options, function (o) { return Number(o.value) === v; })) return;
    var o = document.createElement('option');
    o.value = String(v); o.textContent = v + 'x';
    sel.appendChild(o);
  });
  ['rays', 'trails', 'sightings'].forEach(function (id) { $(id).addEventListener('change', function () { draw(); }); });
  $('follow').addEventListener('change', function () { follow(frames[state.frame]); draw(); });
  // the canvas pixel under a mouse or pointer event, or under a point of
  // the window (inside the canvas's border; the canvas may be shown scaled)
  function eventPixel(e) { return pixelAt(e.clientX, e.clientY); }
  function pixelAt(clientX, clientY) {
    var r = canvas.getBoundingClientRect();
    return [(clientX - r.left - canvas.clientLeft) * canvas.width / canvas.clientWidth,
            (clientY - r.top - canvas.clientTop) * canvas.height / canvas.clientHeight];
  }
  canvas.addEventListener('wheel', function (e) {
    e.preventDefault();
    var p = eventPixel(e);
    // (a wheel that counts in lines or pages, as Firefox's may, is taken
    // at 40 pixels a line; a touchpad's pinch comes as the wheel with the
    // control key, in small steps, which zoom more a pixel than a wheel's)
    var dy = e.deltaY * (e.deltaMode === 1 ? 40 : e.deltaMode === 2 ? 800 : 1);
    zoomAt(p[0], p[1], Math.exp(-dy * (e.ctrlKey && Math.abs(dy) < 50 ? 0.01 : 0.002)));
    drawSoon();
  }, { passive: false });
  // The pointers down on the canvas (the mouse's left button, a pen,
  // fingers), by id, and the gesture they make. One pointer drags: the view
  // moves with it (a press that moves less than 4 CSS pixels with the
  // mouse, 10 with a finger or a pen, is a click or a tap). Two pinch: the
  // view zooms by the change of their distance and keeps the world point
  // that was under their midpoint under it as it moves. When a pointer is
  // added or lifted, the gesture starts again from the view as it is, so
  // lifting one finger of a pinch goes on as a drag, without a jump. A
  // drag or a pinch that moves the view unticks "follow" when a robot is
  // selected (the next frame would take the view back; one that cannot
  // move it, as in the whole world's view, leaves it be), and the click
  // that ends a drag, or follows two pointers, selects nothing. Each
  // pointer is captured: a drag ends where it is released, on the canvas
  // or not. A click selects the robot within 3 canvas pixels of it; a
  // tap, the robot within 16 CSS pixels of the finger (8 of a pen), as a
  // finger covers more than it points at. A finger's or a pen's tap
  // selects when it is lifted, and the click that may follow a finger's
  // or a pen's press ('lastKind', the kind of the last press) is passed
  // over.
  var pointers = {}, gesture = null, dragged = false, lastKind = 'mouse', selections = 0;
  // (in the order of their ids: the first two are the pinch's)
  function pointerList() {
    return Object.keys(pointers).map(Number).sort(function (a, b) { return a - b; }).map(function (k) { return pointers[k]; });
  }
  function startGesture() {
    var ps = pointerList();
    if (ps.length === 0) gesture = null;
    else if (ps.length === 1) gesture = { at: ps[0].at, client: ps[0].client, cx: view.cx, cy: view.cy };
    else {
      var mid = [(ps[0].at[0] + ps[1].at[0]) / 2, (ps[0].at[1] + ps[1].at[1]) / 2];
      gesture = { pinch: true, world: toWorld(mid[0], mid[1]), zoom: view.zoom,
                  dist: Math.max(1, Math.hypot(ps[1].at[0] - ps[0].at[0], ps[1].at[1] - ps[0].at[1])) };
    }
  }
  // a change of the view by a gesture: follow is unticked if it moved
  function moveView(change) {
    var before = viewKey;
    change();
    if (viewKey !== before) {
      if (state.selected >= 0) $('follow').checked = false;
      drawSoon();
    }
  }
  canvas.addEventListener('pointerdown', function (e) {
    if (e.pointerType === 'mouse' && e.button !== 0) return;
    if (Object.keys(pointers).length === 0) dragged = false;
    lastKind = e.pointerType;
    pointers[e.pointerId] = { at: eventPixel(e), client: [e.clientX, e.clientY], slop: e.pointerType === 'mouse' ? 4 : 10 };
    if (canvas.setPointerCapture) { try { canvas.setPointerCapture(e.pointerId); } catch (err) { /* gone already */ } }
    if (Object.keys(pointers).length > 1) dragged = true;
    startGesture();
  });
  canvas.addEventListener('pointermove', function (e) {
    if (!(e.pointerId in pointers) || !gesture) return;
    var q = pointers[e.pointerId];
    q.at = eventPixel(e);
    q.client = [e.clientX, e.clientY];
    var ps = pointerList();
    if (gesture.pinch) {
      var mid = [(ps[0].at[0] + ps[1].at[0]) / 2, (ps[0].at[1] + ps[1].at[1]) / 2];
      moveView(function () {
        placeAt(gesture.world, mid[0], mid[1],
                gesture.zoom * Math.hypot(ps[1].at[0] - ps[0].at[0], ps[1].at[1] - ps[0].at[1]) / gesture.dist);
      });
      return;
    }
    var p = ps[0], dx = p.at[0] - gesture.at[0], dy = p.at[1] - gesture.at[1];
    if (Math.abs(p.client[0] - gesture.client[0]) + Math.abs(p.client[1] - gesture.client[1]) >= p.slop) dragged = true;
    if (dragged) moveView(function () { setView(view.zoom, gesture.cx - dx / scale, gesture.cy + dy / scale); });
  });
  function pointerGone(e) {
    if (!(e.pointerId in pointers)) return;
    delete pointers[e.pointerId];
    startGesture();
  }
  // the robot a click or a tap at a canvas pixel selects (a finger's and a
  // pen's reach in CSS pixels, the mouse's in the canvas's pixels at its
  // own size, the CSS pixels of a canvas not scaled to fit)
  function select(p, kind) {
    state.selected = robotAt(p[0], p[1], kind === 'mouse' ? 3 * dpr : (kind === 'touch' ? 16 : 8) * canvas.width / canvas.clientWidth);
    selections++;
    draw();
  }
  // (a tap selects when it is lifted, not on its click: Chromium fires no
  // click for the tap right after a flick, a drag lifted while the finger
  // still moved, which would otherwise select nothing)
  canvas.addEventListener('pointerup', function (e) {
    var alone = e.pointerId in pointers && Object.keys(pointers).length === 1;
    pointerGone(e);
    if (e.pointerType !== 'mouse' && alone && !dragged) select(eventPixel(e), e.pointerType);
  });
  canvas.addEventListener('pointercancel', pointerGone);
  canvas.addEventListener('lostpointercapture', pointerGone);
  canvas.addEventListener('click', function (e) {
    if (dragged || lastKind !== 'mouse') { dragged = false; return; }
    select(eventPixel(e), 'mouse');
  });
  // (a zoom with the buttons or keys keeps a followed robot in view, paused
  // too: it used to wait for the frame to change; the wheel zooms about
  // the pointer, where the user looks)
  function zoomMiddle(factor) { zoomAt(canvas.width / 2, canvas.height / 2, factor); follow(frames[state.frame]); draw(); }
  function fit() { setView(1, b.x, b.y); draw(); }
  $('zoomin').addEventListener('click', function () { zoomMiddle(1.5); });
  $('zoomout').addEventListener('click', function () { zoomMiddle(1 / 1.5); });
  $('fit').addEventListener('click', fit);
  // whether an element is a button or a tick box that has the focus from
  // the keyboard (Tab), not from a click or a tap: 'focusByKeys', set as
  // the focus moves, unless a press of the mouse, a finger or a pen came
  // after the last key (the browser's :focus-visible will not do: Chrome
  // turns it on at any key, Space's own keydown too)
  var focusByKeys = false, pressed = false;
  document.addEventListener('pointerdown', function () { pressed = true; focusByKeys = false; }, true);
  document.addEventListener('keydown', function () { pressed = false; }, true);
  document.addEventListener('focusin', function () { focusByKeys = !pressed; });
  function keyboardControl(el) {
    return focusByKeys && el === document.activeElement &&
           (el.tagName === 'BUTTON' || (el.tagName === 'INPUT' && el.type === 'checkbox'));
  }
  document.addEventListener('keydown', function (e) {
    if (e.target && e.target.tagName === 'SELECT') return;
    // (a key with Ctrl, Meta or Alt is the browser's: Ctrl+0, Ctrl+plus
    // and Ctrl+minus zoom the page, Alt+left goes back; Shift is left in,
    // as + is Shift+= on many keyboards)
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    // (Space on a button or a tick box reached with the keyboard, Tab, is
    // the control's: it presses the button or ticks the box, as a user of
    // the keyboard expects; it played instead. After a click, which also
    // leaves the focus on the control, it plays, as elsewhere on the page:
    // Space after a click on the step button plays rather than steps
    // again.)
    if (e.key === ' ' && keyboardControl(e.target)) return;
    if (e.key === ' ') { e.preventDefault(); setPlaying(!state.playing); }
    else if (e.key === 'ArrowLeft') { e.preventDefault(); setPlaying(false); setFrame(state.frame - 1); }
    else if (e.key === 'ArrowRight') { e.preventDefault(); setPlaying(false); setFrame(state.frame + 1); }
    else if (e.key === '+' || e.key === '=') zoomMiddle(1.5);
    else if (e.key === '-') zoomMiddle(1 / 1.5);
    else if (e.key === '0') fit();
  });
  // (a thinned page's rate, such as 25/9, to four figures at most)
  $('meta').textContent = header.commandLine.join(' ') + '\n' + 'dt ' + header.dt + ' s, ' + Number(header.fps.toPrecision(4)) +
    ' frames/s, seed ' + header.seed + ', ' + counted(header.robots.length, 'robot') +
    (summary ? '; ' + summary.simulated.toFixed(2) + ' s simulated in ' + counted(summary.steps, 'step') +
               (summary.interrupted ? ' (interrupted)' : '') + (summary.failure ? '; FAILED: ' + summary.failure : '') +
               (falsified ? '; FAILED: ' + falsified.text : '')
             : '; no summary (the run stopped early)');

  // For tests and tools: the page's state, in world and canvas coordinates.
  var api = window.afrpReplay = {
    header: header, summary: summary,
    frameCount: function () { return frames.length; },
    frame: function () { return state.frame; },
    frameData: function (i) { return frames[i == null ? state.frame : i]; },
    setFrame: setFrame,
    play: function () { setPlaying(true); },
    pause: function () { setPlaying(false); },
    playing: function () { return state.playing; },
    selectRobot: function (i) { state.selected = i; draw(); },
    selected: function () { return state.selected; },
    selections: function () { return selections; },
    worldToCanvas: toCanvas,
    canvasToWorld: toWorld,
    // the view: {zoom, cx, cy} (zoom 1 shows the whole world; (cx, cy) is
    // the world point in the middle), and setting it (within its limits)
    view: function () { return { zoom: view.zoom, cx: view.cx, cy: view.cy }; },
    setView: function (zoom, cx, cy) { setView(zoom, cx, cy); draw(); },
    maxZoom: maxZoom,
    // how many robots the last frame drawn drew (those in view), how many
    // of their ids, where (each id's box: the robot, and x, y, width and
    // height in the canvas's pixels, y its top), and whether its trails
    // were rough (see drawTrails)
    drawn: function () {
      return { robots: drawn.robots, labels: drawn.labels, roughTrails: trailsRough,
               labelBoxes: drawn.labelBoxes.map(function (k) {
                 return { robot: k.robot, x: k.x, y: k.y, width: k.width, height: k.height };
               }) };
    },
    // the frame that a property was decided false at, which the page
    // opens at (-1 if none)
    falsifiedFrame: falsifiedFrame,
    // above how many stretches of path (robots times frames) the trails are
    // rough while the view changes
    roughAbove: 200000
  };
  setFrame(Math.max(0, falsifiedFrame));
  window.addEventListener('resize', rescale);
  watchRatio();
})();
