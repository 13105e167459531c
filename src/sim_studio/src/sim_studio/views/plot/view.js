// Plot: rqt_plot. Type a topic field as rqt_plot takes it (/sine/data, /joint_states/position[0])
// and press "+"; several series share one axis against sim time. Pause freezes the view (data
// keeps coming), the wheel zooms the time window (shift+wheel the y axis), "auto y" or fixed
// limits, CSV (every sample the server holds) and PNG (the chart as drawn).
//
// Drawn with uPlot (vendored, /vendor/uplot/). window.studio.plot.series() hands the tests the
// points received, per series.

import uPlot from '/vendor/uplot/uPlot.esm.js';
import {el, clear} from '/dom.js';

const COLORS = ['#1f77b4', '#d62728', '#2ca02c', '#ff7f0e', '#9467bd', '#8c564b', '#e377c2', '#17becf', '#7f7f7f', '#bcbd22'];
const MAX_POINTS = 60000;  // per series in the page: older points go first

function loadStyle(href) {
  if (!document.querySelector(`link[href="${href}"]`)) document.head.append(el('link', {rel: 'stylesheet', href}));
}

// The index of the first element of the sorted array `xs` that is >= x.
function lowerBound(xs, x) {
  let lo = 0; let hi = xs.length;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (xs[mid] < x) lo = mid + 1; else hi = mid;
  }
  return lo;
}

export default function mount(element, studio) {
  loadStyle('/vendor/uplot/uPlot.min.css');
  const pathInput = el('input', {id: 'plot-path', list: 'plot-fields', size: 40, placeholder: '/topic/field, e.g. /joint_states/position[0]'});
  const fieldList = el('datalist', {id: 'plot-fields'});
  const add = el('button', {id: 'plot-add', title: 'add this field'}, '+');
  const pause = el('button', {id: 'plot-pause'}, 'Pause');
  const clearButton = el('button', {id: 'plot-clear'}, 'Clear');
  const windowInput = el('input', {id: 'plot-window', type: 'number', value: '10', min: '0.1', step: 'any', size: 5});
  const yAuto = el('input', {id: 'plot-yauto', type: 'checkbox', checked: true});
  const yMin = el('input', {id: 'plot-ymin', type: 'number', step: 'any', size: 6, value: '-1'});
  const yMax = el('input', {id: 'plot-ymax', type: 'number', step: 'any', size: 6, value: '1'});
  const csvButton = el('button', {id: 'plot-csv'}, 'CSV');
  const pngButton = el('button', {id: 'plot-png'}, 'PNG');
  const error = el('div', {id: 'plot-error', class: 'tool-error'});
  const seriesList = el('div', {id: 'plot-series', class: 'tool-bar'});
  const chartBox = el('div', {id: 'plot-chart', class: 'plot-chart'});
  element.append(
    el('div', {class: 'tool-bar'}, pathInput, fieldList, add, pause, clearButton,
      el('label', {title: 'seconds of time shown (wheel on the plot)'}, 'window (s) ', windowInput),
      el('label', {}, yAuto, ' auto y'), el('label', {}, 'y ', yMin, ' to ', yMax), csvButton, pngButton),
    error, seriesList, chartBox);

  const series = new Map();  // path -> {t: [], v: [], color, error}
  let paused = false;
  let frozenEnd = null;      // the window's right edge while paused
  let chart = null;
  let drawPending = false;
  let offset = null;         // subtracted from times on the axis (wall-clock times are ~1.7e9)

  // --- series ----------------------------------------------------------------------------
  async function addSeries(path) {
    error.textContent = '';
    try {
      const reply = await studio.request('add', {path});
      series.set(reply.path, {t: [], v: [], color: COLORS[series.size % COLORS.length], error: ''});
      pathInput.value = '';
      rebuild();
    } catch (e) {
      error.textContent = e.message;
    }
  }

  async function removeSeries(path) {
    series.delete(path);
    rebuild();
    try { await studio.request('remove', {path}); } catch (e) { /* already gone */ }
  }

  function showSeriesList() {
    clear(seriesList);
    for (const [path, s] of series) {
      const remove = el('button', {class: 'plot-remove', title: `remove ${path}`}, '×');
      remove.addEventListener('click', () => removeSeries(path));
      seriesList.append(el('span', {class: 'plot-chip', 'data-path': path, style: `border-color: ${s.color}`},
        el('span', {style: `color: ${s.color}`}, '■ '), path, s.error ? el('span', {class: 'tool-error'}, ` ${s.error}`) : '', remove));
    }
  }

  studio.on('data', (message) => {
    for (const [path, d] of Object.entries(message.series)) {
      const s = series.get(path);
      if (!s) continue;
      if (offset === null && d.t.length) {
        offset = d.t[0] > 1e5 ? Math.floor(d.t[0]) : 0;
        rebuild();  // the axis label names the offset
      }
      for (let k = 0; k < d.t.length; k++) {
        // times only go forward on one axis: a simulator reset starts the series again
        if (s.t.length && d.t[k] < s.t[s.t.length - 1]) { s.t.length = 0; s.v.length = 0; }
        s.t.push(d.t[k]);
        s.v.push(d.v[k]);
      }
      if (s.t.length > MAX_POINTS) { s.t.splice(0, s.t.length - MAX_POINTS); s.v.splice(0, s.v.length - MAX_POINTS); }
    }
    for (const [path, text] of Object.entries(message.errors || {})) {
      if (series.has(path)) series.get(path).error = text;
      showSeriesList();
    }
    scheduleDraw();
  });

  // --- drawing -----------------------------------------------------------------------------
  function windowLength() {
    const w = Number(windowInput.value);
    return w > 0 ? w : 10;
  }

  function latestTime() {
    let end = -Infinity;
    for (const s of series.values()) if (s.t.length) end = Math.max(end, s.t[s.t.length - 1]);
    return end;
  }

  let shown = {start: 0, end: 10};  // the x range drawn, in the axis' time (offset taken off)

  function visibleData() {
    const end = paused && frozenEnd !== null ? frozenEnd : latestTime();
    const start = end - windowLength();
    shown = Number.isFinite(end) ? {start: start - (offset || 0), end: end - (offset || 0)} : {start: 0, end: windowLength()};
    const tables = [];
    for (const s of series.values()) {
      const from = lowerBound(s.t, start);
      const to = lowerBound(s.t, end + 1e-9);
      const xs = s.t.slice(from, to).map((t) => t - (offset || 0));
      tables.push([xs, s.v.slice(from, to)]);
    }
    if (!tables.length) return [[]];
    return tables.length === 1 ? tables[0] : uPlot.join(tables);
  }

  function size() {
    // the chart fills its box; uPlot's legend (values under the cursor) takes ~40 px below it
    const width = chartBox.clientWidth || element.clientWidth - 20;
    return {width: Math.max(200, width - 4), height: Math.max(200, (chartBox.clientHeight || 420) - 48)};
  }

  function rebuild() {
    showSeriesList();
    if (chart) { chart.destroy(); chart = null; }
    if (!series.size) return;
    const opts = {
      ...size(),
      scales: {
        x: {time: false, range: () => [shown.start, shown.end]},
        y: {range: (u, min, max) => {
          if (!yAuto.checked) return [Number(yMin.value), Number(yMax.value)];
          if (min == null || max == null) return [-1, 1];
          const pad = (max - min) * 0.05 || Math.abs(max) * 0.05 || 1;
          return [min - pad, max + pad];
        }},
      },
      axes: [{label: offset ? `time − ${offset} (s)` : 'time (s)'}, {}],
      series: [{label: 'time'}, ...[...series].map(([path, s]) => ({label: path, stroke: s.color, width: 1.5, spanGaps: true, points: {show: false}}))],
      cursor: {drag: {x: false, y: false}},
    };
    chart = new uPlot(opts, visibleData(), chartBox);
    scheduleDraw();
  }

  function scheduleDraw() {
    if (drawPending || paused) return;
    drawPending = true;
    requestAnimationFrame(draw);
  }

  function draw() {
    drawPending = false;
    if (!chart) return;
    chart.setData(visibleData());
  }

  // --- controls ----------------------------------------------------------------------------
  const redraw = () => { if (chart) chart.setData(visibleData()); };
  add.addEventListener('click', () => addSeries(pathInput.value));
  pathInput.addEventListener('keydown', (event) => { if (event.key === 'Enter') addSeries(pathInput.value); });
  pathInput.addEventListener('focus', async () => {
    try {
      const reply = await studio.request('fields');
      clear(fieldList);
      for (const path of reply.paths) fieldList.append(el('option', {value: path}));
    } catch (e) { /* completion is a help only */ }
  });
  pause.addEventListener('click', () => {
    paused = !paused;
    frozenEnd = paused ? latestTime() : null;
    pause.textContent = paused ? 'Resume' : 'Pause';
    pause.classList.toggle('active', paused);
    if (!paused) scheduleDraw();
  });
  clearButton.addEventListener('click', async () => {
    for (const s of series.values()) { s.t.length = 0; s.v.length = 0; }
    try { await studio.request('clear'); } catch (e) { error.textContent = e.message; }
    redraw();
  });
  for (const input of [windowInput, yMin, yMax]) input.addEventListener('input', redraw);
  yAuto.addEventListener('change', redraw);
  chartBox.addEventListener('wheel', (event) => {
    event.preventDefault();
    const factor = event.deltaY > 0 ? 1.25 : 0.8;
    if (event.shiftKey) {  // zoom y about the middle of what is shown
      const [lo, hi] = [chart.scales.y.min, chart.scales.y.max];
      const mid = (lo + hi) / 2; const half = (hi - lo) / 2 * factor;
      yAuto.checked = false;
      yMin.value = (mid - half).toPrecision(4);
      yMax.value = (mid + half).toPrecision(4);
    } else {
      windowInput.value = String(Number((windowLength() * factor).toPrecision(3)));
    }
    redraw();
  }, {passive: false});

  function download(name, blob) {
    const link = el('a', {href: URL.createObjectURL(blob), download: name});
    document.body.append(link);
    link.click();
    setTimeout(() => { URL.revokeObjectURL(link.href); link.remove(); }, 1000);
  }
  csvButton.addEventListener('click', async () => {
    try {
      const reply = await studio.request('csv');
      download('plot.csv', new Blob([reply.csv], {type: 'text/csv'}));
    } catch (e) { error.textContent = e.message; }
  });
  function png() {
    // the chart's canvas on white, with the series' names (uPlot's legend is HTML, not drawn)
    const source = chart.ctx.canvas;
    const canvas = el('canvas', {width: source.width, height: source.height + 24 * series.size});
    const ctx = canvas.getContext('2d');
    ctx.fillStyle = '#fff';
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    ctx.drawImage(source, 0, 0);
    ctx.font = `${14 * devicePixelRatio}px sans-serif`;
    let y = source.height + 18;
    for (const [path, s] of series) { ctx.fillStyle = s.color; ctx.fillText(`■ ${path}`, 10, y); y += 24; }
    return canvas;
  }
  pngButton.addEventListener('click', () => {
    if (chart) png().toBlob((blob) => download('plot.png', blob), 'image/png');
  });

  studio.onShow(() => { if (chart) { chart.setSize(size()); redraw(); } });
  window.addEventListener('resize', () => { if (chart) chart.setSize(size()); });

  window.studio = window.studio || {};
  window.studio.plot = {
    // what the page received, per series: {path: {t: [...], v: [...]}} (times in s, as sent)
    series: () => Object.fromEntries([...series].map(([path, s]) => [path, {t: [...s.t], v: [...s.v], error: s.error}])),
    // what the chart holds now: [xs, ys per series] (the window only)
    drawn: () => (chart ? chart.data.map((column) => Array.from(column)) : []),
    paused: () => paused,
    png: () => (chart ? png().toDataURL('image/png') : null),
    csv: () => studio.request('csv').then((reply) => reply.csv),  // what the CSV button saves
  };
}
