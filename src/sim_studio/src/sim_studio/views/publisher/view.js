// Publisher: rqt's Message Publisher. Add a publisher (topic, type, rate), write an expression
// per field, tick "publish" to send at the rate or press "once". The server checks every field
// before anything goes out; its error (naming the field) shows on the publisher's row.

import {el, clear} from '/dom.js';

export default function mount(element, studio) {
  const topicInput = el('input', {id: 'publisher-topic', list: 'publisher-topics', placeholder: '/command', size: 32});
  const typeInput = el('input', {id: 'publisher-type', list: 'publisher-types', placeholder: 'std_msgs/Float64', size: 28});
  const rateInput = el('input', {id: 'publisher-rate', type: 'number', value: '1', min: '0', step: 'any', size: 6});
  const addButton = el('button', {id: 'publisher-add'}, 'Add publisher');
  const topicList = el('datalist', {id: 'publisher-topics'});
  const typeList = el('datalist', {id: 'publisher-types'});
  const error = el('div', {id: 'publisher-error', class: 'tool-error'});
  const list = el('div', {id: 'publisher-list'});
  const knownTypes = new Map();  // topic -> type, from the master

  element.append(
    el('div', {class: 'tool-bar'},
      el('label', {}, 'Topic ', topicInput), el('label', {}, 'Type ', typeInput),
      el('label', {}, 'Rate (Hz) ', rateInput), addButton, topicList, typeList),
    error, list,
    el('p', {class: 'tool-hint'},
      'Expressions as in rqt: i is the publish count (1 for the first message), t the ROS time in seconds, ' +
      "math's functions and constants by name (sin(i/100), pi) or as math.sin; also random(), uniform(a, b), " +
      'gauss(m, s), randint(a, b), time(). Lists for arrays, dicts for messages; a string field takes its text.'));

  async function loadLists() {
    try {
      const [topics, types] = await Promise.all([studio.request('topics'), studio.request('types')]);
      clear(topicList);
      for (const topic of topics.topics) {
        knownTypes.set(topic.name, topic.type);
        topicList.append(el('option', {value: topic.name}, topic.type));
      }
      clear(typeList);
      for (const type of types.types) typeList.append(el('option', {value: type}));
    } catch (e) {
      error.textContent = e.message;
    }
  }
  studio.onShow(loadLists);
  loadLists();

  topicInput.addEventListener('change', () => {
    const type = knownTypes.get(topicInput.value.trim());
    if (type && !typeInput.value.trim()) typeInput.value = type;  // rqt fills the type of a known topic
  });

  addButton.addEventListener('click', async () => {
    error.textContent = '';
    try {
      const reply = await studio.request('add', {topic: topicInput.value, msg_type: typeInput.value});
      list.append(publisherRow(reply, Number(rateInput.value)));
    } catch (e) {
      error.textContent = e.message;
    }
  });

  const rows = new Map();  // publisher id -> {status(reply), fail(text)}

  function publisherRow(info, rate) {
    const enabled = el('input', {type: 'checkbox', class: 'publisher-enabled', title: 'publish at the rate'});
    const rateField = el('input', {type: 'number', class: 'publisher-rate', value: String(rate), min: '0', step: 'any', size: 6});
    const once = el('button', {class: 'publisher-once'}, 'Publish once');
    const remove = el('button', {class: 'publisher-remove'}, 'Remove');
    const status = el('span', {class: 'publisher-status'});
    const fields = el('table', {class: 'tool-table publisher-fields'},
      el('tr', {}, el('th', {}, 'field'), el('th', {}, 'type'), el('th', {}, 'expression')));
    const row = el('div', {class: 'publisher', 'data-publisher': String(info.publisher), 'data-topic': info.topic},
      el('div', {class: 'tool-bar'}, enabled, el('b', {}, info.topic), el('span', {class: 'tool-type'}, info.msg_type),
        el('label', {}, 'rate ', rateField), once, remove, status),
      fields);
    addFieldRows(fields, info.fields, 0);

    const expressions = () => {
      const out = {};
      for (const input of fields.querySelectorAll('input.publisher-expression')) {
        if (input.value.trim()) out[input.dataset.path] = input.value;
      }
      return out;
    };
    const show = (reply) => {
      enabled.checked = reply.enabled;
      status.className = 'publisher-status';
      status.textContent = `${reply.count} published${reply.enabled ? ` at ${reply.rate} Hz` : ''}`;
    };
    const fail = (text) => {
      status.className = 'publisher-status tool-error';
      status.textContent = text;
    };
    rows.set(info.publisher, {show, fail, enabled});
    const set = async () => {
      try {
        show(await studio.request('set', {publisher: info.publisher, enabled: enabled.checked,
                                          rate: Number(rateField.value), fields: expressions()}));
      } catch (e) {
        enabled.checked = false;  // shown as it is: a failed change leaves the publisher as it was
        fail(e.message);
      }
    };
    enabled.addEventListener('change', set);
    rateField.addEventListener('change', () => { if (enabled.checked) set(); });
    fields.addEventListener('change', () => { if (enabled.checked) set(); });
    once.addEventListener('click', async () => {
      try {
        show(await studio.request('once', {publisher: info.publisher, fields: expressions()}));
      } catch (e) {
        fail(e.message);
      }
    });
    remove.addEventListener('click', async () => {
      try { await studio.request('remove', {publisher: info.publisher}); } catch (e) { /* already gone */ }
      rows.delete(info.publisher);
      row.remove();
    });
    return row;
  }

  function addFieldRows(table, tree, depth) {
    for (const field of tree) {
      const input = el('input', {class: 'publisher-expression', 'data-path': field.path, size: 30,
                                 placeholder: field.children ? '(fields below, or a dict)' : ''});
      table.append(el('tr', {'data-path': field.path},
        el('td', {style: `padding-left: ${6 + 14 * depth}px`}, field.name),
        el('td', {class: 'tool-type'}, field.type), el('td', {}, input)));
      if (field.children) addFieldRows(table, field.children, depth + 1);
    }
  }

  window.studio = window.studio || {};
  // for the tests: the view's own requests, as its controls send them
  window.studio.publisher = {request: (type, fields) => studio.request(type, fields)};

  studio.on('status', (message) => {
    const row = rows.get(message.publisher);
    if (!row) return;
    if (message.error) {
      row.enabled.checked = false;
      row.fail(message.error);
    } else {
      row.show(message);
    }
  });
}
