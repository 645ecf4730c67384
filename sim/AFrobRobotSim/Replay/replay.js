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
  var frames = lines.filter(function (l) { return l.kind === 'frame'; });
  var summary = lines.filter(function (l) { return l.kind === 'summary'; })[0] || null;
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
  var margin = 10;
  var scale = Math.min(620 / b.width, 620 / b.height);
  canvas.width = Math.round(b.width * scale + 2 * margin);
  canvas.height = Math.round(b.height * scale + 2 * margin);
  // In a big world a robot is a few pixels across: its rim, heading mark and
  // id shrink with it (full size from 30 px/m up, the notes' world included).
  var fine = Math.min(1, scale / 30);

  var state = { frame: 0, playing: false, selected: -1, speed: 1, simTime: 0, last: null };

  function toCanvas(x, y) { return [margin + (x - x0) * scale, margin + (y1 - y) * scale]; }
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

  function rect(r, fill) {
    var p = toCanvas(r.x - r.width / 2, r.y + r.height / 2);
    ctx.fillStyle = fill;
    ctx.fillRect(p[0], p[1], r.width * scale, r.height * scale);
  }
  function disc(x, y, radius, fill, stroke, width) {
    var p = toCanvas(x, y);
    ctx.beginPath(); ctx.arc(p[0], p[1], radius * scale, 0, 2 * Math.PI);
    ctx.fillStyle = fill; ctx.fill();
    if (stroke) { ctx.lineWidth = width; ctx.strokeStyle = stroke; ctx.stroke(); }
  }
  function line(a, c, colour, width, dash) {
    ctx.beginPath(); ctx.setLineDash(dash || []);
    ctx.moveTo(a[0], a[1]); ctx.lineTo(c[0], c[1]);
    ctx.lineWidth = width; ctx.strokeStyle = colour; ctx.stroke(); ctx.setLineDash([]);
  }

  // The trails, on a layer of their own that keeps the paths up to the
  // frame they were last drawn for: going forward adds only the new
  // stretch of each path (playing a big world's page draws a few
  // segments a robot per frame, not its whole path again); going back
  // draws the paths afresh. (Drawn whole at every frame, the trails of
  // 1000 robots took 0.4 s a frame near the end of a 30 s page.)
  var trailLayer = document.createElement('canvas');
  trailLayer.width = canvas.width; trailLayer.height = canvas.height;
  var tctx = trailLayer.getContext('2d');
  var trailsUpTo = -1;   // the layer holds the paths of frames 0 to this one
  function drawTrails(upTo) {
    if (upTo < trailsUpTo) { tctx.clearRect(0, 0, trailLayer.width, trailLayer.height); trailsUpTo = -1; }
    if (upTo > trailsUpTo) {
      var from = Math.max(trailsUpTo, 0);
      header.robots.forEach(function (r, i) {
        tctx.beginPath();
        for (var j = from; j <= upTo; j++) {
          var p = toCanvas(frames[j].robots[i].x, frames[j].robots[i].y);
          if (j === from) tctx.moveTo(p[0], p[1]); else tctx.lineTo(p[0], p[1]);
        }
        tctx.lineWidth = 1; tctx.strokeStyle = rgb(blend(0.5, typeColour(r.type), background)); tctx.stroke();
      });
      trailsUpTo = upTo;
    }
    ctx.drawImage(trailLayer, 0, 0);
  }

  function draw() {
    var f = frames[state.frame];
    ctx.fillStyle = rgb(background); ctx.fillRect(0, 0, canvas.width, canvas.height);
    var c0 = toCanvas(x0, y1);
    ctx.lineWidth = 2; ctx.strokeStyle = 'rgb(45,45,45)';
    ctx.strokeRect(c0[0], c0[1], b.width * scale, b.height * scale);
    header.goals.forEach(function (g) { rect(g, 'rgba(60,170,60,0.25)'); });
    header.walls.forEach(function (w) { rect(w, 'rgb(90,90,90)'); });
    header.blocks.forEach(function (k) { rect(k, 'rgb(139,90,43)'); });
    if ($('trails').checked) drawTrails(state.frame);
    f.balls.forEach(function (p) { disc(p[0], p[1], header.ballRadius, 'rgb(255,140,0)', 'rgb(170,90,0)', 1.5 * fine); });
    f.robots.forEach(function (r, i) {
      var here = toCanvas(r.x, r.y);
      if ($('rays').checked) {
        header.rangeAngles.forEach(function (a, k) {
          var d = r.range[k]; if (d === null) return;
          line(here, toCanvas(r.x + d * Math.cos(r.heading + a), r.y + d * Math.sin(r.heading + a)),
               'rgb(0,170,60)', 1);
        });
      }
      if ($('sightings').checked) {
        var sight = function (a, d, colour) {
          line(here, toCanvas(r.x + d * Math.cos(r.heading + a), r.y + d * Math.sin(r.heading + a)), colour, 1, [4, 3]);
        };
        r.seenRobots.forEach(function (s) { sight(s[2], s[3], 'rgba(120,40,160,0.8)'); });
        r.seenBalls.forEach(function (s) { sight(s[0], s[1], 'rgba(200,110,0,0.8)'); });
      }
    });
    f.robots.forEach(function (r, i) {
      var info = header.robots[i], col = colours[i];
      disc(r.x, r.y, info.radius, rgb(r.bumper ? darken(0.6, col) : col),
           r.bumper ? 'rgb(0,0,0)' : rgb(darken(0.5, col)), i === state.selected ? Math.max(2, 4 * fine) : 2 * fine);
      line(toCanvas(r.x, r.y), toCanvas(r.x + info.radius * Math.cos(r.heading), r.y + info.radius * Math.sin(r.heading)),
           'rgb(255,255,255)', 3 * fine);
      var p = toCanvas(r.x, r.y);
      ctx.fillStyle = 'rgb(20,20,20)'; ctx.font = Math.round(Math.max(8, 12 * fine)) + 'px sans-serif';
      ctx.fillText(String(info.id), p[0] + info.radius * scale + 2, p[1] - info.radius * scale);
    });
    $('time').textContent = 't = ' + f.t.toFixed(2) + ' s  (frame ' + state.frame + ' of ' + (frames.length - 1) + ')';
    $('slider').value = String(state.frame);
    $('play').textContent = state.playing ? 'Pause' : 'Play';
    showInfo();
    showEvents();
  }

  function num(x, d) { return x === null ? 'n/a' : x.toFixed(d === undefined ? 3 : d); }
  function showInfo() {
    var el = $('info');
    if (state.selected < 0) { el.textContent = 'Click a robot to see its readings.'; return; }
    var i = state.selected, info = header.robots[i], r = frames[state.frame].robots[i];
    var out = [];
    out.push(info.type + ' ' + info.id + '   at t = ' + frames[state.frame].t.toFixed(2) + ' s');
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
    out.push('messages (up to now, newest last):');
    var msgs = [];
    for (var j = 0; j <= state.frame; j++) {
      frames[j].robots[i].messages.forEach(function (m) { msgs.push('  [' + m[0].toFixed(2) + '] ' + m[1]); });
    }
    if (msgs.length === 0) msgs.push('  none');
    el.textContent = out.concat(msgs.slice(-50)).join('\n');
  }
  function showEvents() {
    var evs = [];
    for (var j = 0; j <= state.frame; j++) {
      frames[j].events.forEach(function (e) { evs.push('[' + e.t.toFixed(2) + '] ' + e.kind + ': ' + e.text); });
      frames[j].console.forEach(function (c) { evs.push(c); });
    }
    $('events').textContent = evs.slice(-30).join('\n');
  }

  function setFrame(i) {
    state.frame = Math.max(0, Math.min(frames.length - 1, Math.round(i)));
    state.simTime = frames[state.frame].t;
    draw();
  }
  function setPlaying(p) {
    state.playing = p && frames.length > 1;
    if (state.playing && state.frame >= frames.length - 1) setFrame(0);
    state.last = null;
    draw();
    if (state.playing) requestAnimationFrame(tick);
  }
  function tick(now) {
    if (!state.playing) return;
    if (state.last !== null) {
      state.simTime += (now - state.last) / 1000 * state.speed;
      var i = state.frame;
      while (i + 1 < frames.length && frames[i + 1].t <= state.simTime) i++;
      if (i !== state.frame) { state.frame = i; draw(); }
      if (i >= frames.length - 1) { state.playing = false; draw(); return; }
    }
    state.last = now;
    requestAnimationFrame(tick);
  }
  function robotAt(px, py) {
    var f = frames[state.frame], best = -1, bestD = Infinity;
    f.robots.forEach(function (r, i) {
      var p = toCanvas(r.x, r.y), d = Math.hypot(p[0] - px, p[1] - py);
      if (d <= header.robots[i].radius * scale + 3 && d < bestD) { best = i; bestD = d; }
    });
    return best;
  }

  $('slider').max = String(frames.length - 1);
  $('slider').addEventListener('input', function () { setFrame(Number($('slider').value)); });
  $('play').addEventListener('click', function () { setPlaying(!state.playing); });
  $('back').addEventListener('click', function () { setPlaying(false); setFrame(state.frame - 1); });
  $('fwd').addEventListener('click', function () { setPlaying(false); setFrame(state.frame + 1); });
  $('speed').addEventListener('change', function () { state.speed = Number($('speed').value); });
  ['rays', 'trails', 'sightings'].forEach(function (id) { $(id).addEventListener('change', draw); });
  canvas.addEventListener('click', function (e) {
    var r = canvas.getBoundingClientRect();
    state.selected = robotAt((e.clientX - r.left) * canvas.width / r.width, (e.clientY - r.top) * canvas.height / r.height);
    draw();
  });
  document.addEventListener('keydown', function (e) {
    if (e.target && e.target.tagName === 'SELECT') return;
    if (e.key === ' ') { e.preventDefault(); setPlaying(!state.playing); }
    else if (e.key === 'ArrowLeft') { e.preventDefault(); setPlaying(false); setFrame(state.frame - 1); }
    else if (e.key === 'ArrowRight') { e.preventDefault(); setPlaying(false); setFrame(state.frame + 1); }
  });
  $('meta').textContent = header.commandLine.join(' ') + '\n' + 'dt ' + header.dt + ' s, ' + header.fps +
    ' frames/s, seed ' + header.seed + ', ' + header.robots.length + ' robots' +
    (summary ? '; ' + summary.simulated.toFixed(2) + ' s simulated in ' + summary.steps + ' steps' +
               (summary.interrupted ? ' (interrupted)' : '') + (summary.failure ? '; FAILED: ' + summary.failure : '')
             : '; no summary (the run stopped early)');

  // For tests and tools: the page's state, in world and canvas coordinates.
  window.afrpReplay = {
    header: header, summary: summary,
    frameCount: function () { return frames.length; },
    frame: function () { return state.frame; },
    frameData: function (i) { return frames[i === undefined ? state.frame : i]; },
    setFrame: setFrame,
    play: function () { setPlaying(true); },
    pause: function () { setPlaying(false); },
    playing: function () { return state.playing; },
    selectRobot: function (i) { state.selected = i; draw(); },
    selected: function () { return state.selected; },
    worldToCanvas: toCanvas
  };
  setFrame(0);
})();
