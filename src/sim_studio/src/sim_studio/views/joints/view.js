// Joints: Gazebo's joint panel for the selected model. Three tabs, as Gazebo's: Force (one
// number per joint), Position (target, P, I, D) and Velocity (target, P, I, D). As in Gazebo,
// a value takes effect as soon as it is entered (the input's change: Enter or leaving the field)
// and stays until changed or Reset; a gain changed before its target was set waits for the
// target. Gazebo's default gains: P 1, I 0.1, D 0.01.
import {element} from '/dom.js';

const POLL_MS = 250;
const DEFAULT_GAINS = {p: 1, i: 0.1, d: 0.01};
const TABS = ['force', 'position', 'velocity'];


function units(type) {
  const linear = type === 'prismatic';
  return {force: linear ? 'N' : 'N·m', position: linear ? 'm' : 'rad', velocity: linear ? 'm/s' : 'rad/s'};
}

export default function mount(root, studio) {
  document.head.appendChild(element('link', {rel: 'stylesheet', href: '/views/joints/joints.css'}));
  const modelLabel = element('span', {id: 'joints-model', text: 'none'});
  const reset = element('button', {id: 'joints-reset', text: 'Reset', disabled: ''});
  const tabBar = element('div', {class: 'joint-tabs'});
  const panes = {};
  for (const tab of TABS) {
    const button = element('button', {'data-tab': tab, text: tab[0].toUpperCase() + tab.slice(1)});
    button.addEventListener('click', () => showTab(tab));
    tabBar.append(button);
    panes[tab] = element('div', {class: 'joint-pane', id: `joints-${tab}`, 'data-tab': tab});
  }
  const status = element('div', {class: 'joints-status', id: 'joints-status', role: 'status'});
  root.append(element('h2', {text: 'Joints'}),
      element('div', {class: 'joints-head'}, element('span', {text: 'Model: '}), modelLabel, reset),
      tabBar, ...Object.values(panes), status);

  let model = null;
  let joints = [];
  let generation = 0;

  function say(text, isError = false) {
    status.textContent = text;
    status.classList.toggle('error', isError);
    if (isError) studio.status(`joints: ${text}`, true);
  }

  function showTab(tab) {
    for (const button of tabBar.children) button.classList.toggle('active', button.dataset.tab === tab);
    for (const [name, pane] of Object.entries(panes)) pane.classList.toggle('active', name === tab);
  }
  showTab('force');

  function numberInput(joint, tab, field, value) {
    return element('input', {type: 'text', inputmode: 'decimal', size: '6', value: String(value),
      'data-joint': joint, 'data-tab': tab, 'data-field': field, 'aria-label': `${joint} ${tab} ${field}`});
  }

  // One row per joint and tab: its name and current value, then the inputs.
  function layout(list) {
    for (const pane of Object.values(panes)) pane.replaceChildren();
    if (!list.length) {
      for (const pane of Object.values(panes)) pane.append(element('p', {class: 'note', text: model ? 'This model has no joints.' : 'Select a model.'}));
      return;
    }
    for (const joint of list) {
      const u = units(joint.type);
      for (const tab of TABS) {
        const current = element('span', {class: 'current', 'data-joint': joint.name});
        const row = element('div', {class: 'joint-row', 'data-joint': joint.name},
            element('div', {class: 'joint-name'}, element('span', {text: joint.name}), current));
        if (tab === 'force') {
          row.append(element('label', {}, numberInput(joint.name, tab, 'force', 0), element('span', {class: 'unit', text: u.force})));
        } else {
          const fields = element('div', {class: 'pid'});
          fields.append(element('label', {}, element('span', {text: 'target'}), numberInput(joint.name, tab, 'target', 0),
              element('span', {class: 'unit', text: u[tab]})));
          for (const gain of ['p', 'i', 'd']) {
            fields.append(element('label', {}, element('span', {text: gain.toUpperCase()}), numberInput(joint.name, tab, gain, DEFAULT_GAINS[gain])));
          }
          row.append(fields);
        }
        panes[tab].append(row);
      }
    }
  }

  function readNumber(input) {
    if (input.value.trim() === '') return null;  // cleared, to be typed into: nothing to apply yet
    const value = Number(input.value.trim());
    const ok = Number.isFinite(value);
    input.classList.toggle('invalid', !ok);
    if (!ok) say(`${input.dataset.joint}: ${input.dataset.field}: expected a number, got '${input.value}'`, true);
    return ok ? value : null;
  }

  // Gazebo's panel: a force or target entered becomes active (and is sent); a gain is sent
  // with the target when that is active.
  async function onChange(event) {
    const input = event.target;
    if (input.tagName !== 'INPUT') return;
    const {joint, tab, field} = input.dataset;
    const row = input.closest('.joint-row');
    if (readNumber(input) === null) return;
    let command;
    if (tab === 'force') {
      command = {force: readNumber(input)};
    } else {
      if (field !== 'target' && !row.classList.contains('active')) return;
      const pid = {};
      for (const f of ['target', 'p', 'i', 'd']) {
        const value = readNumber(row.querySelector(`input[data-field="${f}"]`));
        if (value === null) return;
        pid[f] = value;
      }
      command = {[tab]: pid};
    }
    row.classList.add('active');
    try {
      await studio.request('command', {model, joint, ...command});
      say(`${joint}: ${tab} ${tab === 'force' ? command.force : `target ${command[tab].target}`} applied`);
    } catch (error) {
      row.classList.remove('active');
      say(error.message, true);
    }
  }
  for (const pane of Object.values(panes)) pane.addEventListener('change', onChange);

  reset.addEventListener('click', async () => {
    if (!model) return;
    try {
      await studio.request('reset', {model});
      for (const row of root.querySelectorAll('.joint-row')) {
        row.classList.remove('active');
        for (const input of row.querySelectorAll('input[data-field="force"], input[data-field="target"]')) input.value = '0';
      }
      say(`${model}: commands reset`);
    } catch (error) {
      say(error.message, true);
    }
  });

  async function select(name) {
    if (name === model) return;
    model = name;
    generation += 1;
    const mine = generation;
    modelLabel.textContent = name || 'none';
    reset.toggleAttribute('disabled', !name);
    joints = [];
    layout(joints);
    if (!name) return;
    try {
      const reply = await studio.request('joints', {model: name});
      if (mine !== generation) return;
      joints = reply.joints;
      layout(joints);
      poll(mine);
    } catch (error) {
      say(error.message, true);
    }
  }

  // The joints' current positions (Force and Position tabs) and velocities (Velocity tab).
  async function poll(mine) {
    while (mine === generation) {
      try {
        const reply = await studio.request('positions', {model});
        if (mine !== generation) return;
        for (const span of root.querySelectorAll('.current')) {
          const state = reply.joints[span.dataset.joint];
          const velocity = span.closest('.joint-pane').dataset.tab === 'velocity';
          span.textContent = state ? (velocity ? state.rate : state.position).toFixed(4) : '–';
        }
      } catch (error) {
        if (mine === generation) say(error.message, true);
      }
      await new Promise((resolve) => setTimeout(resolve, POLL_MS));
    }
  }

  studio.bus.addEventListener('select', (event) => select(event.detail.model));
  layout([]);
  window.studio = window.studio || {};
  window.studio.joints = {model: () => model, select};
}
