// Models: the tree of models -> links and joints, the selected model's properties, delete and
// insert. The selection is shared on the bus ("select", detail {model, source}), so a click
// here selects in the World and Joints views and a click in the World selects here.
import {element} from '/dom.js';

const STATE_PERIOD_MS = 250;  // the selected model's pose, twist and joints, a few times a second


// -0.000 reads as a sign where there is none: values that round to zero show as 0.
const fixed = (values, digits = 3) => values.map((v) => (v == null ? '–' : (Math.abs(v) < 0.5 * 10 ** -digits ? 0 : v).toFixed(digits))).join('  ');

export default function mount(root, studio) {
  const link = element('link', {rel: 'stylesheet', href: '/views/models/models.css'});
  document.head.appendChild(link);
  const tree = element('ul', {class: 'model-tree', id: 'models-tree'});
  const props = element('div', {class: 'model-props', id: 'models-props'});
  const status = element('div', {class: 'models-status', id: 'models-status', role: 'status'});
  const insert = buildInsert();
  root.append(element('h2', {text: 'Models'}), tree, props, insert.section, status);

  let models = [];
  let selected = null;
  let generation = 0;  // a new selection stops the previous one's state polling
  let centre = {x: 0, y: 0, z: 0};

  function say(text, isError = false) {
    status.textContent = text;
    status.classList.toggle('error', isError);
    if (isError) studio.status(`models: ${text}`, true);
  }

  // --- the tree -----------------------------------------------------------------------------
  function drawTree() {
    tree.replaceChildren();
    for (const model of models) {
      const item = element('li', {'data-model': model.name, class: model.name === selected ? 'selected' : ''});
      const toggle = element('span', {class: 'toggle', text: '▸'});
      const label = element('span', {class: 'label', text: model.name});
      const children = element('ul', {class: 'children'});
      children.append(element('li', {class: 'group', text: `links (${model.links.length})`}));
      for (const name of model.links) children.append(element('li', {class: 'link', 'data-link': name, text: name}));
      children.append(element('li', {class: 'group', text: `joints (${model.joints.length})`}));
      for (const name of model.joints) children.append(element('li', {class: 'joint', 'data-joint': name, text: name}));
      toggle.addEventListener('click', (event) => {
        event.stopPropagation();
        item.classList.toggle('open');
        toggle.textContent = item.classList.contains('open') ? '▾' : '▸';
      });
      label.addEventListener('click', () => select(model.name, true));
      item.append(toggle, label, children);
      tree.append(item);
    }
  }

  studio.on('tree', (message) => {
    models = message.models || [];
    if (message.error) say(message.error, true);
    drawTree();
    if (selected && !models.some((m) => m.name === selected)) select(null, false);
  });

  // --- selection and properties ---------------------------------------------------------------
  function select(name, fromHere) {
    if (name === selected) return;
    selected = name;
    generation += 1;
    for (const item of tree.children) item.classList.toggle('selected', item.dataset.model === name);
    props.replaceChildren();
    if (fromHere) studio.bus.dispatchEvent(new CustomEvent('select', {detail: {model: name, source: 'models'}}));
    if (name) showDetails(name, generation);
  }

  studio.bus.addEventListener('select', (event) => {
    if (event.detail.source !== 'models') select(event.detail.model, false);
  });
  studio.bus.addEventListener('view-centre', (event) => { centre = event.detail; });

  async function showDetails(name, mine) {
    let details;
    try {
      details = await studio.request('details', {model: name});
    } catch (error) {
      say(error.message, true);
      return;
    }
    if (mine !== generation) return;
    const remove = element('button', {id: 'models-delete', text: 'Delete'});
    remove.addEventListener('click', () => removeModel(name));
    const table = element('table', {class: 'props'});
    const row = (key, value, id) => table.append(element('tr', {}, element('th', {text: key}),
        element('td', id ? {id, text: value} : {text: value})));
    row('model', name);
    row('static', details.static ? 'yes' : 'no');
    row('position (m)', '', 'models-position');
    row('roll pitch yaw', '', 'models-rpy');
    row('linear (m/s)', '', 'models-linear');
    row('angular (rad/s)', '', 'models-angular');
    const links = element('table', {class: 'props', id: 'models-links'});
    links.append(element('tr', {}, element('th', {text: 'link'}), element('th', {text: 'mass (kg)'})));
    for (const l of details.links) {
      const mass = l.mass == null ? (details.masses ? '–' : 'n/a') : l.mass.toFixed(3);
      links.append(element('tr', {'data-link': l.name}, element('td', {text: l.name}), element('td', {class: 'mass', text: mass})));
    }
    const joints = element('table', {class: 'props', id: 'models-joints'});
    joints.append(element('tr', {}, element('th', {text: 'joint'}), element('th', {text: 'type'}),
        element('th', {text: 'position'})));
    for (const j of details.joints) {
      joints.append(element('tr', {'data-joint': j.name}, element('td', {text: j.name}), element('td', {text: j.type}),
          element('td', {class: 'position'})));
    }
    props.replaceChildren(element('div', {class: 'buttons'}, remove), table, links, joints);
    if (!details.masses) props.append(element('p', {class: 'note', text: 'Masses: the simulator offers no /gazebo/get_link_properties.'}));
    pollState(name, mine);
  }

  async function pollState(name, mine) {
    while (mine === generation) {
      try {
        const state = await studio.request('state', {model: name});
        if (mine !== generation) return;
        document.getElementById('models-position').textContent = fixed(state.position);
        document.getElementById('models-rpy').textContent = fixed(state.rpy);
        document.getElementById('models-linear').textContent = fixed(state.linear);
        document.getElementById('models-angular').textContent = fixed(state.angular);
        for (const row of props.querySelectorAll('#models-joints tr[data-joint]')) {
          const value = state.joints[row.dataset.joint];
          row.querySelector('.position').textContent = value == null ? '–' : value.toFixed(4);
        }
      } catch (error) {
        if (mine === generation) say(error.message, true);
      }
      await new Promise((resolve) => setTimeout(resolve, STATE_PERIOD_MS));
    }
  }

  async function removeModel(name) {
    try {
      const reply = await studio.request('delete', {model: name});
      say(reply.status || `deleted ${name}`);
    } catch (error) {
      say(error.message, true);
    }
  }

  // --- insert ---------------------------------------------------------------------------------
  function buildInsert() {
    const section = element('details', {class: 'model-insert', id: 'models-insert-section'});
    const library = element('select', {id: 'models-library'});
    const add = element('button', {id: 'models-insert', text: 'Insert'});
    const where = element('div', {class: 'where'});
    const fields = {};
    for (const axis of ['x', 'y', 'z']) {
      fields[axis] = element('input', {id: `models-${axis}`, type: 'text', size: '5', placeholder: axis === 'z' ? 'ground' : 'centre'});
      where.append(element('label', {text: axis}), fields[axis]);
    }
    const shapes = element('div', {class: 'shapes'});
    for (const shape of ['box', 'sphere', 'cylinder']) {
      const button = element('button', {'data-shape': shape, text: shape});
      button.addEventListener('click', () => insertModel({shape}));
      shapes.append(button);
    }
    add.addEventListener('click', () => {
      if (library.value) insertModel({key: library.value}); else say('choose a model to insert', true);
    });
    section.append(element('summary', {text: 'Insert'}), where, element('div', {class: 'row'}, library, add), shapes);
    section.addEventListener('toggle', () => { if (section.open && !library.options.length) loadLibrary(library); });
    return {section, fields, library};
  }

  async function loadLibrary(library) {
    try {
      const reply = await studio.request('library');
      library.replaceChildren(...reply.models.map((m) => element('option', {value: m.key, title: m.description, text: m.name})));
      if (!reply.models.length) say('no models in GAZEBO_MODEL_PATH, ~/.gazebo/models or the packages\' models/ folders');
    } catch (error) {
      say(error.message, true);
    }
  }

  async function insertModel(what) {
    // Empty x, y: the point the World view looks at; empty z: standing on the ground.
    const request = {...what};
    for (const axis of ['x', 'y', 'z']) {
      const text = insert.fields[axis].value.trim();
      if (text) request[axis] = text; else if (axis !== 'z') request[axis] = centre[axis];
    }
    try {
      const reply = await studio.request('insert', request);
      say(`inserted ${reply.model}`);
    } catch (error) {
      say(error.message, true);
    }
  }

  studio.request('tree').then((reply) => {
    models = reply.models || [];
    drawTree();
  }).catch((error) => say(error.message, true));

  window.studio = window.studio || {};
  window.studio.models = {select: (name) => select(name, true), selected: () => selected};
}
