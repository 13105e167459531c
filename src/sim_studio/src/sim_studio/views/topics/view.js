// Topics: rqt's Topic Monitor. One row per topic (type, publishers, bandwidth, rate); the
// checkbox measures it (the server subscribes only then), clicking the name echoes its newest
// message as a tree of fields, as rostopic echo prints it.

import {el, clear} from '/dom.js';

export function formatBandwidth(bytesPerSecond) {
  // rostopic bw's units: decimal kilo and mega
  if (bytesPerSecond == null) return '';
  if (bytesPerSecond < 1000) return `${bytesPerSecond.toFixed(2)} B/s`;
  if (bytesPerSecond < 1e6) return `${(bytesPerSecond / 1000).toFixed(2)} KB/s`;
  return `${(bytesPerSecond / 1e6).toFixed(2)} MB/s`;
}

export default function mount(element, studio) {
  const filter = el('input', {id: 'topics-filter', placeholder: 'filter topics', size: 24});
  const refresh = el('button', {id: 'topics-refresh'}, 'Refresh');
  const error = el('div', {class: 'tool-error', id: 'topics-error'});
  const body = el('tbody');
  const table = el('table', {class: 'tool-table', id: 'topics-table'},
    el('thead', {}, el('tr', {}, el('th', {}, ''), el('th', {}, 'topic'), el('th', {}, 'type'),
      el('th', {title: 'publishers / subscribers'}, 'pub/sub'), el('th', {}, 'bandwidth'), el('th', {}, 'Hz'))),
    body);
  const echoTitle = el('h3', {id: 'topics-echo-title'}, 'Echo: click a topic');
  const echoBody = el('div', {id: 'topics-echo', class: 'tool-tree'});
  element.append(el('div', {class: 'tool-bar'}, filter, refresh), error,
    el('div', {class: 'tool-split'}, el('div', {class: 'tool-pane'}, table),
      el('div', {class: 'tool-pane'}, echoTitle, echoBody)));

  const rows = new Map();     // topic -> {row, cells}
  const monitored = new Set();
  const collapsed = new Set(); // echo tree paths the user folded
  let echoTopic = null;

  function rowFor(topic) {
    if (rows.has(topic.name)) return rows.get(topic.name);
    const check = el('input', {type: 'checkbox', class: 'topics-monitor', title: 'monitor rate and bandwidth'});
    const name = el('a', {href: '#', class: 'topics-name'}, topic.name);
    const cells = {type: el('td', {class: 'topics-type tool-type'}), pubsub: el('td', {class: 'topics-pubsub'}),
                   bandwidth: el('td', {class: 'topics-bandwidth'}), rate: el('td', {class: 'topics-rate'})};
    const row = el('tr', {'data-topic': topic.name}, el('td', {}, check), el('td', {}, name),
      cells.type, cells.pubsub, cells.bandwidth, cells.rate);
    check.addEventListener('change', async () => {
      try {
        await studio.request('monitor', {topic: topic.name, on: check.checked});
        if (check.checked) monitored.add(topic.name); else monitored.delete(topic.name);
        if (!check.checked) { cells.rate.textContent = ''; cells.bandwidth.textContent = ''; }
      } catch (e) {
        check.checked = false;
        error.textContent = e.message;
      }
    });
    name.addEventListener('click', (event) => {
      event.preventDefault();
      echo(topic.name);
    });
    const entry = {row, cells};
    rows.set(topic.name, entry);
    return entry;
  }

  function showList(message) {
    error.textContent = message.error || '';
    const seen = new Set();
    const wanted = filter.value.trim();
    clear(body);
    for (const topic of message.topics) {
      seen.add(topic.name);
      const {row, cells} = rowFor(topic);
      cells.type.textContent = topic.type;
      cells.pubsub.textContent = `${topic.publishers} / ${topic.subscribers}`;
      row.dataset.type = topic.type;
      row.dataset.publishers = topic.publishers;
      if (!wanted || topic.name.includes(wanted) || topic.type.includes(wanted)) body.append(row);
    }
    for (const name of [...rows.keys()]) if (!seen.has(name) && !monitored.has(name)) rows.delete(name);
  }

  let lastList = {topics: []};
  studio.on('list', (message) => { lastList = message; showList(message); });
  filter.addEventListener('input', () => showList(lastList));
  refresh.addEventListener('click', async () => {
    try { lastList = await studio.request('refresh'); showList(lastList); } catch (e) { error.textContent = e.message; }
  });

  studio.on('stats', (message) => {
    for (const [topic, s] of Object.entries(message.stats)) {
      const entry = rows.get(topic);
      if (!entry) continue;
      // as rostopic hz says "no new messages": no rate once the topic fell silent
      const silent = s.age == null || s.age > Math.max(3, s.rate ? 3 / s.rate : 0);
      entry.cells.rate.textContent = s.rate == null ? '' : (silent ? 'no new messages' : s.rate.toFixed(2));
      entry.cells.bandwidth.textContent = formatBandwidth(s.bandwidth);
      entry.row.dataset.rate = s.rate == null || silent ? '' : String(s.rate);
      entry.row.dataset.bandwidth = s.bandwidth == null ? '' : String(s.bandwidth);
    }
  });

  async function echo(topic) {
    if (topic === echoTopic) topic = null;  // the echoed topic clicked again: echo nothing
    try {
      await studio.request('echo', {topic});
      echoTopic = topic;
      echoTitle.textContent = topic ? `Echo: ${topic} (waiting for a message)` : 'Echo: click a topic';
      for (const [name, entry] of rows) entry.row.classList.toggle('selected', name === topic);
      clear(echoBody);
    } catch (e) {
      error.textContent = e.message;
    }
  }

  studio.on('echo', (message) => {
    if (message.topic !== echoTopic) return;
    echoTitle.textContent = `Echo: ${message.topic} (${message.msg_type}, ${message.count} received)`;
    clear(echoBody);
    if (message.error) echoBody.append(el('div', {class: 'tool-error'}, message.error));
    else echoBody.append(tree(message.fields, ''));
  });

  function tree(nodes, prefix) {
    const list = el('ul');
    for (const node of nodes) {
      const path = prefix + '/' + node.name;
      if (node.children) {
        const details = el('details', {open: !collapsed.has(path)},
          el('summary', {}, el('b', {}, node.name), ' ', el('span', {class: 'tool-type'}, node.type)),
          tree(node.children, path));
        details.addEventListener('toggle', () => {
          if (details.open) collapsed.delete(path); else collapsed.add(path);
        });
        if (node.more) details.append(el('div', {class: 'tool-type'}, `… ${node.more} more`));
        list.append(el('li', {'data-path': path}, details));
      } else {
        const value = Array.isArray(node.value) ? `[${node.value.join(', ')}${node.more ? `, … ${node.more} more` : ''}]`
                                              : String(node.value);
        list.append(el('li', {'data-path': path}, el('b', {}, node.name), ': ',
          el('span', {class: 'topics-value'}, value), ' ', el('span', {class: 'tool-type'}, node.type)));
      }
    }
    return list;
  }
}
