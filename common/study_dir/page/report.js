/* report.html's script (embedded by cmake/embed_report.cmake; README.md, "The
 * comparison page"). Plain ES5, no framework, no network: the study's files are
 * the JSON in #fs-data (the CSVs' text, report.md, the PNGs' names) and the
 * images load by relative path. The numbers shown are the CSVs' own. */
(function () {
  'use strict';
  var D = JSON.parse(document.getElementById('fs-data').textContent);
  var app = document.getElementById('app');

  function el(tag, attrs, text) {
    var e = document.createElement(tag);
    for (var k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    return e;
  }
  function svg(tag, attrs) {
    var e = document.createElementNS('http://www.w3.org/2000/svg', tag);
    for (var k in attrs || {}) e.setAttribute(k, attrs[k]);
    return e;
  }

  /* A table's text: provenance (the "# ..." line), header, rows (objects). */
  function parseCSV(text) {
    var out = { prov: '', header: [], rows: [] };
    if (!text) return null;
    var lines = text.split('\n');
    for (var i = 0; i < lines.length; i++) {
      var line = lines[i];
      if (!line) continue;
      if (line.charAt(0) === '#') { if (!out.prov) out.prov = line.replace(/^#\s*/, ''); continue; }
      var f = splitCSV(line);
      if (!out.header.length) { out.header = f; continue; }
      var row = {};
      for (var j = 0; j < out.header.length; j++) row[out.header[j]] = f[j] === undefined ? '' : f[j];
      out.rows.push(row);
    }
    return out;
  }
  function splitCSV(line) {
    var f = [], cur = '', q = false;
    for (var i = 0; i < line.length; i++) {
      var c = line.charAt(i);
      if (q) {
        if (c === '"' && line.charAt(i + 1) === '"') { cur += '"'; i++; }
        else if (c === '"') q = false;
        else cur += c;
      } else if (c === '"') q = true;
      else if (c === ',') { f.push(cur); cur = ''; }
      else cur += c;
    }
    f.push(cur);
    return f;
  }
  function num(s) { return s !== '' && isFinite(+s) ? +s : NaN; }

  var T = { metrics: parseCSV(D.metrics), timings: parseCSV(D.timings), temporal: parseCSV(D.temporal),
            counters: parseCSV(D.counters) };
  var md = D.report_md || '';
  var pngs = {};
  D.pngs.forEach(function (n) { pngs[n] = 1; });

  /* The views: report.md's label table, else the metrics' methods with a PNG. */
  function views() {
    var v = [], inFiles = false;
    md.split('\n').forEach(function (line) {
      if (/^## /.test(line)) inFiles = /^## Files/.test(line);
      var m = inFiles && /^\| `([^`]+)` \| ([^|]*) \| ([^|]*) \|/.exec(line);
      if (!m) return;
      var method = m[2].trim(), settings = m[3].trim(), ref = / \(ground truth\)$/.test(method);
      method = method.replace(/ \(ground truth\)$/, '');
      if (method === 'imported') method = m[1];
      v.push({ label: m[1], method: method, variant: ref ? 'ground truth' : (settings === '—' ? '' : settings), ref: ref });
    });
    if (!v.length && T.metrics) {
      var seen = {};
      T.metrics.rows.forEach(function (r) {
        [[r.method, r.variant, false], [r.reference, 'ground truth', true]].forEach(function (x) {
          var key = x[0] + '\u0001' + x[1];
          if (seen[key] || x[1] && !x[2]) return;
          seen[key] = 1;
          v.push({ label: x[0], method: x[0], variant: x[1], ref: x[2] });
        });
      });
    }
    v.forEach(function (w) {
      var re = new RegExp('^' + w.label.replace(/[-]/g, '\\-') + '_f(\\d{4})\\.png$');
      w.frames = {};
      D.pngs.forEach(function (n) { var m = re.exec(n); if (m) w.frames[+m[1]] = n; });
      if (pngs[w.label + '.png']) w.single = w.label + '.png';
      w.own = pngs[w.label + '_own.png'] ? w.label + '_own.png' : null;
      w.heat = { normal: pngs['heat_normal_' + w.label + '.png'] ? 'heat_normal_' + w.label + '.png' : null,
                 depth: pngs['heat_depth_' + w.label + '.png'] ? 'heat_depth_' + w.label + '.png' : null };
      w.diff = pngs['diff_' + w.label + '.png'] ? 'diff_' + w.label + '.png' : null;
    });
    return v.filter(function (w) { return w.single || Object.keys(w.frames).length; });
  }
  var V = views();
  var methods = V.filter(function (w) { return !w.ref; });
  var refs = V.filter(function (w) { return w.ref; });
  if (!methods.length) methods = V;
  var frameSet = {};
  V.forEach(function (w) { Object.keys(w.frames).forEach(function (f) { frameSet[f] = 1; }); });
  var frames = Object.keys(frameSet).map(Number).sort(function (a, b) { return a - b; });
  var scales = /Heatmap scales: normal ([^ ]+) deg, depth ([^ ]+) r/.exec(md);
  var LAYERS = [['shaded', 'shaded'], ['normal', 'normal error'], ['depth', 'depth error']];

  var S = { cur: 0, ref: 0, flip: false, hoverRef: false, split: false, splitX: 0.5, zoom: 1, base: 1, panX: 0, panY: 0,
            layer: 'shaded', own: false, frame: 0, playing: null, mx: -1, my: -1, sortCol: null, sortDir: 1 };

  /* The file a view shows now. */
  function fileOf(w, layer) {
    if (layer !== 'shaded' && !w.ref) return w.heat[layer];
    var f = frames.length ? frames[S.frame] : null;
    if (f !== null && w.frames[f]) {
      var own = w.label + '_own_f' + ('000' + f).slice(-4) + '.png';
      return S.own && pngs[own] ? own : w.frames[f];
    }
    return S.own && w.own ? w.own : w.single;
  }
  var cache = {};
  function image(name) {
    if (!name) return null;
    if (!cache[name]) { cache[name] = new Image(); cache[name].onload = draw; cache[name].src = encodeURI(name); }
    return cache[name];
  }
  function ready(im) { return im && im.complete && im.naturalWidth > 0; }

  /* ---- the page ---- */
  var title = el('h1', {}, 'fluidsurf study');
  var cmd = /Reproduce with:\s*\n\s*\n\s{4}(.*)/.exec(md);
  app.textContent = '';
  app.appendChild(title);
  if (cmd) app.appendChild(el('div', { 'class': 'mono note', id: 'command' }, cmd[1]));
  var top = el('div', { id: 'top' }), viewer = el('div', { id: 'viewer' }), side = el('div', { id: 'side' });
  app.appendChild(top); top.appendChild(viewer); top.appendChild(side);
  var picker = el('div', { id: 'picker' });
  viewer.appendChild(picker);
  methods.forEach(function (w, i) {
    var b = el('button', { 'data-i': i, title: w.method + (w.variant ? ' ' + w.variant : '') }, (i < 9 ? (i + 1) + ' ' : '') + w.label);
    b.onclick = function () { show(i); };
    picker.appendChild(b);
  });
  var refChip = null;
  if (refs.length && methods !== V) {
    refChip = el('button', { 'class': 'ref', id: 'refchip', title: 'hover or press f: the reference' }, 'f ' + refs[0].label);
    refChip.onmouseenter = function () { S.hoverRef = true; draw(); };
    refChip.onmouseleave = function () { S.hoverRef = false; draw(); };
    refChip.onclick = function () { S.flip = !S.flip; draw(); };
    picker.appendChild(refChip);
  }
  var layersDiv = el('div', { id: 'layers' });
  viewer.appendChild(layersDiv);
  LAYERS.forEach(function (l) {
    var any = l[0] === 'shaded' || methods.some(function (w) { return w.heat[l[0]]; });
    if (!any) return;
    var b = el('button', { 'data-layer': l[0] }, l[1]);
    b.onclick = function () { S.layer = l[0]; draw(); };
    layersDiv.appendChild(b);
  });
  var splitBtn = el('button', { id: 'splitbtn', title: 'd: split line' }, 'split');
  splitBtn.onclick = function () { S.split = !S.split; draw(); };
  layersDiv.appendChild(splitBtn);
  if (!methods.length) viewer.appendChild(el('p', { 'class': 'note', id: 'noimages' },
    'No view\'s PNG is in this folder (LABEL.png or LABEL_fNNNN.png): only the numbers are shown.'));
  var canvas = el('canvas', { id: 'canvas' });
  viewer.appendChild(canvas);
  if (!methods.length) canvas.style.display = layersDiv.style.display = 'none';
  var status = el('div', { id: 'status' });
  viewer.appendChild(status);
  var frameDiv = null, slider = null, playBtn = null;
  if (frames.length > 1) {
    frameDiv = el('div', { id: 'frames' });
    playBtn = el('button', { id: 'play' }, 'play');
    playBtn.onclick = togglePlay;
    slider = el('input', { id: 'frame', type: 'range', min: 0, max: frames.length - 1, value: 0, step: 1 });
    slider.oninput = function () { S.frame = +slider.value; draw(); };
    frameDiv.appendChild(playBtn);
    frameDiv.appendChild(slider);
    frameDiv.appendChild(el('span', { id: 'framelabel' }));
    viewer.appendChild(frameDiv);
  }
  viewer.appendChild(el('div', { 'class': 'note keys' },
    '1-9 / arrows: method · f: flip to the reference (or hover its button) · d: split line (drag it) · l: layer · ' +
    'o: own appearance · wheel, +/-: zoom (to 16x) · drag: pan · r: reset' + (frames.length > 1 ? ' · space: play · n .: next frame · ,: previous' : '')));
  var legend = el('div', { id: 'legend' });
  side.appendChild(legend);
  var grid = el('div', { id: 'grid' });
  side.appendChild(grid);

  /* Canvas size: the image at an integer scale (base) that makes it at least ~384 px,
   * or shrunk to 768 px when it is larger (zooming in then goes to 1x first). */
  function sizeCanvas() {
    var im = image(fileOf(methods[0], 'shaded'));
    if (!ready(im)) return false;
    var w = im.naturalWidth, h = im.naturalHeight, m = Math.max(w, h);
    S.base = m > 768 ? 768 / m : Math.max(1, Math.min(16, Math.floor(384 / m)));
    canvas.width = Math.round(w * S.base); canvas.height = Math.round(h * S.base);
    S.imgW = w; S.imgH = h;
    S.zoom = S.base; S.panX = 0; S.panY = 0;
    return true;
  }

  function show(i) {
    S.cur = (i + methods.length) % methods.length;
    draw();
  }

  function drawImageAt(ctx, im) {
    ctx.setTransform(S.zoom, 0, 0, S.zoom, -S.panX * S.zoom, -S.panY * S.zoom);
    ctx.drawImage(im, 0, 0);
  }

  function draw() {
    if (!methods.length) return;
    if (!S.imgW && !sizeCanvas()) return;
    var ctx = canvas.getContext('2d');
    ctx.imageSmoothingEnabled = S.zoom < 1; /* pixelated from 1x up */
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.fillStyle = '#6b6b6b';
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    var w = methods[S.cur], ref = refs[S.ref];
    var flipped = (S.flip || S.hoverRef) && ref;
    var a = image(fileOf(flipped ? ref : w, flipped ? 'shaded' : S.layer));
    if (ready(a)) drawImageAt(ctx, a);
    var complete = !a || ready(a);
    var sx = Math.round(S.splitX * canvas.width);
    if (S.split && ref && !flipped) {
      var b = image(fileOf(ref, 'shaded'));
      complete = complete && ready(b);
      if (ready(b)) {
        ctx.save();
        ctx.setTransform(1, 0, 0, 1, 0, 0);
        ctx.beginPath(); ctx.rect(sx, 0, canvas.width - sx, canvas.height); ctx.clip();
        drawImageAt(ctx, b);
        ctx.restore();
      }
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      ctx.fillStyle = '#ffcc00';
      ctx.fillRect(sx - 1, 0, 2, canvas.height);
    }
    updateUI(w, flipped, a);
    /* Images load asynchronously: 'data-ready' says the canvas shows every image it wants. */
    status.setAttribute('data-ready', complete ? '1' : '0');
  }

  function pixelUnder() {
    if (S.mx < 0) return null;
    return [Math.floor(S.panX + S.mx / S.zoom), Math.floor(S.panY + S.my / S.zoom)];
  }

  function updateUI(w, flipped, a) {
    [].forEach.call(picker.querySelectorAll('button[data-i]'), function (b) { b.className = +b.getAttribute('data-i') === S.cur ? 'on' : ''; });
    if (refChip) refChip.className = 'ref' + (flipped ? ' on' : '');
    [].forEach.call(layersDiv.querySelectorAll('button[data-layer]'), function (b) { b.className = b.getAttribute('data-layer') === S.layer ? 'on' : ''; });
    splitBtn.className = S.split ? 'on' : '';
    var shown = flipped ? refs[S.ref] : w, p = pixelUnder();
    var txt = 'showing ' + shown.label + (flipped ? ' (reference)' : '') + ' · layer ' + (flipped ? 'shaded' : S.layer);
    if (frames.length) txt += ' · frame ' + frames[S.frame];
    txt += ' · zoom ' + (S.zoom / 1).toFixed(S.zoom < 1 ? 2 : 0) + 'x';
    if (p && p[0] >= 0 && p[1] >= 0 && p[0] < S.imgW && p[1] < S.imgH) txt += ' · pixel ' + p[0] + ',' + p[1];
    if (!a) txt += ' · (no ' + S.layer + ' image for this method)';
    status.textContent = txt;
    status.setAttribute('data-label', shown.label);
    status.setAttribute('data-file', a ? a.getAttribute('src') : '');
    if (slider) { slider.value = S.frame; document.getElementById('framelabel').textContent = ' frame ' + frames[S.frame] + ' (' + (S.frame + 1) + '/' + frames.length + ')'; }
    legend.textContent = '';
    if (S.layer !== 'shaded' && scales)
      legend.appendChild(el('div', { 'class': 'note' }, 'Heatmaps of the first frame against ' + (refs[0] ? refs[0].label : 'the reference') +
        ', the study\'s common scale: normal error 0-' + scales[1] + ' deg, |depth error - bias| 0-' + scales[2] + ' r.'));
    if (w.diff) { var d = el('img', { src: encodeURI(w.diff), alt: w.diff }); legend.appendChild(d); }
    highlight();
    markGrid();
  }

  /* ---- input ---- */
  function zoomAt(f, mx, my) {
    var z = f > 1 ? (S.zoom < 1 ? 1 : Math.min(16, S.zoom * 2)) : (S.zoom <= 1 ? S.base : Math.max(S.base, S.zoom / 2));
    if (z === S.zoom) return;
    var ix = S.panX + mx / S.zoom, iy = S.panY + my / S.zoom;
    S.zoom = z; S.panX = ix - mx / z; S.panY = iy - my / z;
    if (z === S.base) { S.panX = 0; S.panY = 0; }
    draw();
  }
  function canvasXY(ev) {
    var r = canvas.getBoundingClientRect();
    return [ev.clientX - r.left, ev.clientY - r.top];
  }
  canvas.addEventListener('wheel', function (ev) {
    ev.preventDefault();
    var p = canvasXY(ev);
    S.mx = p[0]; S.my = p[1];
    zoomAt(ev.deltaY < 0 ? 2 : 0.5, p[0], p[1]);
  }, { passive: false });
  var drag = null;
  canvas.addEventListener('mousedown', function (ev) {
    var p = canvasXY(ev);
    drag = S.split && Math.abs(p[0] - S.splitX * canvas.width) < 8 ? { split: true } : { x: p[0], y: p[1], px: S.panX, py: S.panY };
    ev.preventDefault();
  });
  window.addEventListener('mouseup', function () { drag = null; });
  canvas.addEventListener('mouseleave', function () { S.mx = -1; draw(); });
  window.addEventListener('mousemove', function (ev) {
    var p = canvasXY(ev), inside = p[0] >= 0 && p[1] >= 0 && p[0] < canvas.width && p[1] < canvas.height;
    if (!drag && !inside) return;
    if (drag && drag.split) S.splitX = Math.max(0, Math.min(1, p[0] / canvas.width));
    else if (drag) { S.panX = drag.px - (p[0] - drag.x) / S.zoom; S.panY = drag.py - (p[1] - drag.y) / S.zoom; }
    S.mx = inside ? p[0] : -1; S.my = p[1];
    canvas.className = S.split && Math.abs(p[0] - S.splitX * canvas.width) < 8 ? 'split-hover' : '';
    draw();
  });
  function togglePlay() {
    if (S.playing) { clearInterval(S.playing); S.playing = null; }
    else S.playing = setInterval(function () { step(1); }, 400);
    if (playBtn) playBtn.textContent = S.playing ? 'pause' : 'play';
  }
  function step(d) { if (frames.length > 1) { S.frame = (S.frame + d + frames.length) % frames.length; draw(); } }
  document.addEventListener('keydown', function (ev) {
    if (ev.target && ev.target.tagName === 'INPUT' && /^Arrow/.test(ev.key)) return; /* the slider's own keys */
    if (ev.ctrlKey || ev.metaKey || ev.altKey) return;
    var k = ev.key, cx = S.mx >= 0 ? S.mx : canvas.width / 2, cy = S.mx >= 0 ? S.my : canvas.height / 2;
    if (/^[1-9]$/.test(k)) { if (+k <= methods.length) show(+k - 1); }
    else if (k === 'ArrowRight' || k === 'ArrowDown') show(S.cur + 1);
    else if (k === 'ArrowLeft' || k === 'ArrowUp') show(S.cur - 1);
    else if (k === 'f' || k === 'g') { S.flip = !S.flip; draw(); }
    else if (k === 'd') { S.split = !S.split; draw(); }
    else if (k === 'l') { var ls = [].map.call(layersDiv.querySelectorAll('button[data-layer]'), function (b) { return b.getAttribute('data-layer'); });
      S.layer = ls[(ls.indexOf(S.layer) + 1) % ls.length]; draw(); }
    else if (k === 'o') { S.own = !S.own; draw(); }
    else if (k === '+' || k === '=') zoomAt(2, cx, cy);
    else if (k === '-') zoomAt(0.5, cx, cy);
    else if (k === 'r') { S.zoom = S.base; S.panX = 0; S.panY = 0; draw(); }
    else if (k === ' ') togglePlay();
    else if (k === 'n' || k === '.') step(1);
    else if (k === ',') step(-1);
    else return;
    ev.preventDefault();
  });

  /* ---- the metrics table ---- */
  function section(id, heading) {
    var s = el('section', { id: id });
    s.appendChild(el('h2', {}, heading));
    app.appendChild(s);
    return s;
  }
  function tableOf(t, id) {
    var wrap = el('div', { 'class': 'scroll' }), tab = el('table', { id: id }), thead = el('thead'), tr = el('tr');
    t.header.forEach(function (h) {
      var isText = t.rows.every(function (r) { return r[h] === '' || isNaN(num(r[h])); });
      var th = el('th', { 'data-col': h, 'class': isText ? 'text' : '' }, h);
      th.onclick = function () { sortBy(t, tab, h); };
      tr.appendChild(th);
    });
    thead.appendChild(tr); tab.appendChild(thead); tab.appendChild(el('tbody'));
    wrap.appendChild(tab);
    t.order = t.rows.slice();
    fillBody(t, tab);
    return wrap;
  }
  function fillBody(t, tab) {
    var tb = tab.tBodies[0];
    tb.textContent = '';
    t.order.forEach(function (r) {
      var tr = el('tr', { 'data-key': r.method + '\u0001' + r.variant, 'data-frame': r.frame === undefined ? '' : r.frame });
      t.header.forEach(function (h) { tr.appendChild(el('td', { 'class': isNaN(num(r[h])) ? 'text' : '' }, r[h])); });
      tb.appendChild(tr);
    });
  }
  function sortBy(t, tab, col) {
    var dir = t.sortCol === col ? -t.sortDir : 1;
    t.sortCol = col; t.sortDir = dir;
    t.order.sort(function (a, b) {
      var x = num(a[col]), y = num(b[col]);
      if (!isNaN(x) && !isNaN(y)) return (x - y) * dir;
      if (isNaN(x) !== isNaN(y)) return isNaN(x) ? 1 : -1; /* empty and text cells last */
      return String(a[col]).localeCompare(String(b[col])) * dir;
    });
    [].forEach.call(tab.tHead.rows[0].cells, function (th) {
      th.classList.remove('sorted-asc', 'sorted-desc');
      if (th.getAttribute('data-col') === col) th.classList.add(dir > 0 ? 'sorted-asc' : 'sorted-desc');
    });
    fillBody(t, tab);
    highlight();
  }
  function highlight() {
    if (!methods.length) return;
    var w = methods[S.cur], key = w.method + '\u0001' + w.variant, f = frames.length ? String(frames[S.frame]) : '';
    [].forEach.call(document.querySelectorAll('#metrics-table tbody tr, #temporal-table tbody tr'), function (tr) {
      var on = tr.getAttribute('data-key') === key;
      tr.className = on ? 'shown' + (f !== '' && tr.getAttribute('data-frame') === f ? ' frame' : '') : '';
    });
  }

  /* ---- a sweep grid: one method swept over one or two parameters ---- */
  /* The method whose rows take more than one value of the swept columns: an older
   * metrics.csv also filled them on other methods' rows (the reference's own field). */
  function sweptMethod(params) {
    var seen = {}, order = [];
    T.metrics.rows.forEach(function (r) {
      if (r[params[0]] === '') return;
      if (!seen[r.method]) { seen[r.method] = []; order.push(r.method); }
      var k = r[params[0]] + '\u0001' + (params[1] ? r[params[1]] : '');
      if (seen[r.method].indexOf(k) < 0) seen[r.method].push(k);
    });
    return order.filter(function (m) { return seen[m].length > 1; })[0];
  }
  function sweepGrid() {
    var mh = T.metrics ? T.metrics.header : [];
    var a = mh.indexOf('variant'), b = mh.indexOf('reference');
    var params = a >= 0 && b > a + 1 ? mh.slice(a + 1, b) : [];
    if (!params.length || params.length > 2) return;
    var byKey = {}, byRow = {}, rows = [], cols = params[1] ? [] : [''], swept = sweptMethod(params);
    T.metrics.rows.forEach(function (r) {
      var i = methods.findIndex(function (w) { return w.method === r.method && w.variant === r.variant; });
      if (i < 0 || r.method !== swept || r[params[0]] === '') return; /* only the swept method's rows */
      var k = r[params[0]] + '\u0001' + (params[1] ? r[params[1]] : '');
      if (byKey[k] === undefined) { byKey[k] = i; byRow[k] = r; } /* the first reference's row */
      if (rows.indexOf(r[params[0]]) < 0) rows.push(r[params[0]]); /* in the study's order */
      if (params[1] && cols.indexOf(r[params[1]]) < 0) cols.push(r[params[1]]);
    });
    if (rows.length * cols.length < 2) return;
    grid.appendChild(el('h2', {}, 'Sweep: ' + params.join(' x ')));
    grid.appendChild(el('div', { 'class': 'note' }, 'Each cell: the variant\'s mean normal error against the first reference and its frame time; click it to show it.'));
    var tab = el('table'), hr = el('tr');
    hr.appendChild(el('th', {}, params[0] + (params[1] ? ' \\ ' + params[1] : '')));
    cols.forEach(function (c) { hr.appendChild(el('th', {}, c)); });
    tab.appendChild(hr);
    rows.forEach(function (rv) {
      var tr = el('tr');
      tr.appendChild(el('th', {}, rv));
      cols.forEach(function (cv) {
        var k = rv + '\u0001' + cv, i = byKey[k], r = byRow[k];
        var td = el('td', { 'data-i': i === undefined ? '' : i, title: i === undefined ? '' : methods[i].label },
                    r ? r.normal_mean_deg + ' deg · ' + r.frame_ms + ' ms' : '');
        if (i !== undefined) td.onclick = function () { show(i); };
        tr.appendChild(td);
      });
      tab.appendChild(tr);
    });
    grid.appendChild(tab);
  }
  function markGrid() {
    [].forEach.call(grid.querySelectorAll('td[data-i]'), function (td) { td.className = td.getAttribute('data-i') === String(S.cur) ? 'on' : ''; });
  }

  /* ---- timings: stacked bars per stage ---- */
  var PALETTE = ['#4e79a7', '#f28e2b', '#e15759', '#76b7b2', '#59a14f', '#edc948', '#b07aa1', '#ff9da7', '#9c755f', '#bab0ac'];
  /* Stage i of n, one colour each across the study: the palette while it lasts, else
   * hues spaced evenly around the wheel, neighbours also apart in lightness. */
  function stageColour(i, n) {
    if (n <= PALETTE.length) return PALETTE[i];
    return 'hsl(' + Math.round(i * 360 / n) + ', 60%, ' + (i % 2 ? 62 : 42) + '%)';
  }
  function timingsChart(t) {
    var groups = [], byKey = {}, stages = [];
    t.rows.forEach(function (r) {
      var key = r.method + '\u0001' + r.variant;
      if (!byKey[key]) { byKey[key] = { name: r.method + (r.variant && r.variant !== 'ground truth' ? ' ' + r.variant : r.variant ? ' (ground truth)' : ''), parts: [] }; groups.push(byKey[key]); }
      var ms = num(r.ms_median);
      if (r.stage === 'total') { byKey[key].reported = ms; return; } /* the median of the runs' totals: the bar's label */
      if (!isNaN(ms)) byKey[key].parts.push({ stage: r.stage, ms: ms, renderer: r.renderer, min: r.ms_min, max: r.ms_max });
      if (stages.indexOf(r.stage) < 0) stages.push(r.stage);
    });
    var maxT = 0;
    groups.forEach(function (g) {
      g.sum = g.parts.reduce(function (s, p) { return s + p.ms; }, 0);
      g.total = g.reported >= 0 ? g.reported : g.sum;
      maxT = Math.max(maxT, g.sum, g.total);
    });
    var left = 200, width = 520, rowH = 20, h = groups.length * rowH + 40;
    var s = svg('svg', { width: left + width + 90, height: h, id: 'timings-svg' });
    groups.forEach(function (g, i) {
      var y = 4 + i * rowH, x = left;
      var lab = svg('text', { x: left - 6, y: y + 13, 'text-anchor': 'end' });
      lab.textContent = g.name;
      s.appendChild(lab);
      g.parts.forEach(function (p) {
        var wpx = maxT > 0 ? p.ms / maxT * width : 0;
        var rect = svg('rect', { x: x, y: y, width: Math.max(wpx, 0.5), height: rowH - 4, fill: stageColour(stages.indexOf(p.stage), stages.length),
                                 'data-stage': p.stage });
        var tt = svg('title');
        tt.textContent = g.name + ' · ' + p.stage + ': ' + p.ms + ' ms (min ' + p.min + ', max ' + p.max + ') on ' + p.renderer;
        rect.appendChild(tt);
        s.appendChild(rect);
        x += wpx;
      });
      var tot = svg('text', { x: x + 4, y: y + 13 });
      tot.textContent = g.total.toFixed(1) + ' ms' + (g.reported >= 0 ? '' : ' (sum of stages)');
      s.appendChild(tot);
    });
    var lx = left, ly = groups.length * rowH + 20;
    stages.forEach(function (st, i) {
      s.appendChild(svg('rect', { x: lx, y: ly, width: 10, height: 10, fill: stageColour(i, stages.length) }));
      var t2 = svg('text', { x: lx + 13, y: ly + 9 });
      t2.textContent = st;
      s.appendChild(t2);
      lx += 20 + st.length * 7;
      if (lx > left + width) { lx = left; ly += 14; s.setAttribute('height', ly + 20); }
    });
    return s;
  }

  if (T.metrics) {
    var ms = section('metrics', 'Metrics (metrics.csv; click a column to sort)');
    ms.appendChild(tableOf(T.metrics, 'metrics-table'));
  }
  if (T.temporal) {
    var ts = section('temporal', 'Temporal measures (temporal.csv)');
    ts.appendChild(tableOf(T.temporal, 'temporal-table'));
  }
  if (T.timings) {
    var tm = section('timings', 'Timings (timings.csv: median per stage; hover a bar for the stage and the renderer)');
    tm.appendChild(timingsChart(T.timings));
  }
  if (T.counters) {
    var cs = section('counters', 'Work counters (counters.csv)');
    cs.appendChild(tableOf(T.counters, 'counters-table'));
  }
  var pv = section('provenance', 'Provenance');
  var ul = el('ul', { id: 'prov' });
  var prov = T.metrics ? T.metrics.prov : '';
  prov.split(/; (?=[a-z_:]+=)/).forEach(function (kv) { if (kv.trim()) ul.appendChild(el('li', {}, kv.replace(/;$/, ''))); });
  pv.appendChild(ul);
  var renderers = {};
  if (T.timings) T.timings.rows.forEach(function (r) { renderers[r.method + (r.variant ? ' ' + r.variant : '')] = r.renderer; });
  var rl = el('ul', { id: 'renderers' });
  Object.keys(renderers).forEach(function (k) { rl.appendChild(el('li', {}, k + ': ' + renderers[k])); });
  pv.appendChild(el('div', { 'class': 'note' }, 'Renderer of each timed method:'));
  pv.appendChild(rl);
  sweepGrid();
  if (prov) { var sc = /scene=([^;]*)/.exec(prov); if (sc) title.textContent = 'fluidsurf study: ' + sc[1]; }
  draw();
})();
