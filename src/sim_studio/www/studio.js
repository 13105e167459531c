// The page shell: one websocket to the studio, each view's module mounted into its slot.
//
// A view's page side is views/<name>/view.js exporting `default function mount(element, studio)`
// where `studio` is that view's handle:
//   studio.send(type, fields)      a message to the view's server side
//   studio.request(type, fields)   the same, as a Promise of the reply (rejected with its error)
//   studio.on(type, handler)       messages of that type from the server side
//   studio.bus                     an EventTarget every view shares ("select" a model, ...)
//   studio.onShow(handler)         the view's tab became visible (resize canvases then)
//   studio.status(text, isError)   a line in the header
// docs/STUDIO.md has an example.

const status = document.getElementById('status');
const bus = new EventTarget();
const handlers = new Map();      // view name -> Map(type -> [handler])
const showHandlers = new Map();  // page id -> [handler]
const pending = new Map();       // request id -> {resolve, reject}
let socket = null;
let nextId = 1;
let queued = [];

function setStatus(text, isError = false) {
  status.textContent = text;
  status.classList.toggle('error', isError);
}

function connect() {
  const scheme = location.protocol === 'https:' ? 'wss' : 'ws';
  socket = new WebSocket(`${scheme}://${location.host}/ws${location.search}`);
  socket.onopen = () => {
    setStatus('connected');
    for (const text of queued) socket.send(text);
    queued = [];
  };
  socket.onmessage = (event) => dispatch(JSON.parse(event.data));
  socket.onclose = () => {
    setStatus('disconnected: reconnecting…', true);
    for (const {reject} of pending.values()) reject(new Error('connection lost'));
    pending.clear();
    setTimeout(connect, 1000);  // the node restarted, or the network blinked
  };
}

function dispatch(message) {
  if (message.id != null && pending.has(message.id)) {
    const {resolve, reject} = pending.get(message.id);
    pending.delete(message.id);
    if (message.type === 'error') reject(new Error(message.error)); else resolve(message);
    return;
  }
  if (message.type === 'error') setStatus(`${message.view || 'studio'}: ${message.error}`, true);
  const byType = handlers.get(message.view);
  for (const handler of (byType && byType.get(message.type)) || []) handler(message);
  bus.dispatchEvent(new CustomEvent('message', {detail: message}));
}

function send(text) {
  if (socket && socket.readyState === WebSocket.OPEN) socket.send(text); else queued.push(text);
}

function handleFor(name, pageId) {
  return {
    name,
    bus,
    send: (type, fields = {}) => send(JSON.stringify({...fields, view: name, type})),
    request: (type, fields = {}) => new Promise((resolve, reject) => {
      const id = nextId++;
      pending.set(id, {resolve, reject});
      send(JSON.stringify({...fields, view: name, type, id}));
    }),
    on: (type, handler) => {
      if (!handlers.has(name)) handlers.set(name, new Map());
      const byType = handlers.get(name);
      if (!byType.has(type)) byType.set(type, []);
      byType.get(type).push(handler);
    },
    onShow: (handler) => {
      if (!showHandlers.has(pageId)) showHandlers.set(pageId, []);
      showHandlers.get(pageId).push(handler);
    },
    status: setStatus,
  };
}

function showPage(pageId) {
  for (const page of document.querySelectorAll('.page')) page.classList.toggle('active', page.id === pageId);
  for (const button of document.querySelectorAll('#tabs button')) {
    button.classList.toggle('active', button.dataset.page === pageId);
  }
  for (const handler of showHandlers.get(pageId) || []) handler();
}

async function mountViews() {
  const views = await (await fetch('/views.json' + location.search)).json();
  const tabs = document.getElementById('tabs');
  for (const view of views) {
    const element = document.createElement('div');
    element.className = 'view';
    element.id = `view-${view.name}`;
    let pageId = 'workspace';
    if (view.slot === 'tab') {
      pageId = `page-${view.name}`;
      const page = document.createElement('section');
      page.className = 'page';
      page.id = pageId;
      page.appendChild(element);
      document.querySelector('main').appendChild(page);
      const button = document.createElement('button');
      button.textContent = view.title;
      button.dataset.page = pageId;
      tabs.appendChild(button);
    } else {
      document.getElementById(`slot-${view.slot}`).appendChild(element);
    }
    try {
      const module = await import(`/views/${view.name}/view.js`);
      module.default(element, handleFor(view.name, pageId));
    } catch (error) {
      element.textContent = `view ${view.name} failed to load: ${error}`;
      console.error(error);
    }
  }
  tabs.addEventListener('click', (event) => {
    if (event.target.dataset.page) showPage(event.target.dataset.page);
  });
  connect();
  window.studioReady = true;  // the browser tests wait for it
}

mountViews();
