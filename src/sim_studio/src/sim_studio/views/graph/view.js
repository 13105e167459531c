// Graph: rqt_graph. Nodes (ellipses) and topics (boxes), laid out by graphviz on the server;
// Refresh asks the master again. The checkboxes are rqt_graph's filters.

import {el, clear} from '/dom.js';

export default function mount(element, studio) {
  const mode = el('select', {id: 'graph-mode'},
    el('option', {value: 'nodes_topics'}, 'Nodes/Topics (all)'), el('option', {value: 'nodes'}, 'Nodes only'));
  const hideDebug = el('input', {type: 'checkbox', id: 'graph-hide-debug', checked: true});
  const hideClock = el('input', {type: 'checkbox', id: 'graph-hide-clock', checked: true});
  const hideLeaf = el('input', {type: 'checkbox', id: 'graph-hide-leaf'});
  const fit = el('input', {type: 'checkbox', id: 'graph-fit', checked: true});
  const refresh = el('button', {id: 'graph-refresh'}, 'Refresh');
  const info = el('span', {id: 'graph-info', class: 'tool-type'});
  const error = el('div', {id: 'graph-error', class: 'tool-error'});
  const canvas = el('div', {id: 'graph-svg', class: 'graph-svg'});
  element.append(el('div', {class: 'tool-bar'}, mode,
    el('label', {}, hideDebug, ' hide debug'), el('label', {}, hideClock, ' hide /clock'),
    el('label', {}, hideLeaf, ' hide leaf topics'), el('label', {}, fit, ' fit'), refresh, info), error, canvas);

  let lastSvg = null;

  function show(svgText) {
    // dot's SVG, parsed as SVG (never as HTML): names in it are text nodes dot escaped
    const doc = new DOMParser().parseFromString(svgText, 'image/svg+xml');
    const svg = document.importNode(doc.documentElement, true);
    if (svg.nodeName !== 'svg') throw new Error('the server sent no SVG');
    if (fit.checked) {  // shrink a large graph to the pane; a small one keeps dot's size
      svg.style.maxWidth = '100%';
      svg.style.maxHeight = '100%';
      svg.style.height = 'auto';
    }
    clear(canvas).append(svg);
  }

  async function load() {
    error.textContent = '';
    refresh.disabled = true;
    try {
      const reply = await studio.request('refresh', {mode: mode.value, hide_debug: hideDebug.checked,
                                                     hide_clock: hideClock.checked, hide_leaf: hideLeaf.checked});
      lastSvg = reply.svg;
      show(reply.svg);
      info.textContent = `${reply.nodes.length} nodes, ${reply.topics.length} topics, ${reply.edges} edges`;
      canvas.dataset.nodes = JSON.stringify(reply.nodes);
      canvas.dataset.topics = JSON.stringify(reply.topics);
    } catch (e) {
      error.textContent = e.message;
    } finally {
      refresh.disabled = false;
    }
  }

  refresh.addEventListener('click', load);
  for (const control of [mode, hideDebug, hideClock, hideLeaf]) control.addEventListener('change', load);
  fit.addEventListener('change', () => { if (lastSvg) show(lastSvg); });
  studio.onShow(load);
}
