// Images: image_view. Pick an image topic; its newest frames arrive as JPEG (at most 15 a
// second). "dynamic range" scales depth images from their own nearest to farthest value,
// as image_view's do_dynamic_scaling; otherwise 0 to 10 m, image_view's default.

import {el, clear} from '/dom.js';

export default function mount(element, studio) {
  const topic = el('select', {id: 'images-topic'}, el('option', {value: ''}, '(choose an image topic)'));
  const refresh = el('button', {id: 'images-refresh'}, 'Refresh');
  const dynamic = el('input', {type: 'checkbox', id: 'images-dynamic'});
  const info = el('span', {id: 'images-info', class: 'tool-type'});
  const error = el('div', {id: 'images-error', class: 'tool-error'});
  const image = el('img', {id: 'images-frame', class: 'images-frame', alt: ''});
  element.append(el('div', {class: 'tool-bar'}, topic, refresh, el('label', {}, dynamic, ' dynamic range'), info),
    error, el('div', {class: 'images-box'}, image));

  let frames = 0;
  let since = performance.now();
  let fps = 0;

  let listed = '';
  async function listTopics() {
    try {
      const reply = await studio.request('topics');
      const names = JSON.stringify(reply.topics);
      if (names === listed) return;  // unchanged: keep the options (and what is being chosen)
      listed = names;
      const chosen = topic.value;
      clear(topic).append(el('option', {value: ''}, '(choose an image topic)'));
      for (const t of reply.topics) topic.append(el('option', {value: t.name}, `${t.name} (${t.type.split('/')[1]})`));
      if (chosen && !reply.topics.some((t) => t.name === chosen)) topic.append(el('option', {value: chosen}, chosen));
      topic.value = chosen;
    } catch (e) {
      error.textContent = e.message;
    }
  }

  async function watch() {
    error.textContent = '';
    image.removeAttribute('src');
    frames = 0;
    since = performance.now();
    info.textContent = topic.value ? 'waiting for a frame' : '';
    try {
      await studio.request('watch', {topic: topic.value || null, dynamic: dynamic.checked});
    } catch (e) {
      error.textContent = e.message;
    }
  }

  studio.on('frame', (message) => {
    if (message.topic !== topic.value) return;
    if (message.error) {
      error.textContent = message.error;
      return;
    }
    error.textContent = '';
    image.src = `data:image/jpeg;base64,${message.jpeg}`;
    image.dataset.seq = message.seq;
    frames += 1;
    const now = performance.now();
    if (now - since > 1000) { fps = frames * 1000 / (now - since); frames = 0; since = now; }
    info.textContent = `${message.width}×${message.height} ${message.encoding}, ${fps.toFixed(1)} frames/s`;
  });

  topic.addEventListener('change', watch);
  dynamic.addEventListener('change', watch);
  refresh.addEventListener('click', listTopics);
  studio.onShow(listTopics);
  listTopics();

  window.studio = window.studio || {};
  window.studio.images = {
    // the shown frame's pixel at (x, y) as [r, g, b, a], read back through a canvas
    pixel: (x, y) => {
      if (!image.complete || !image.naturalWidth) return null;
      const canvas = el('canvas', {width: image.naturalWidth, height: image.naturalHeight});
      const ctx = canvas.getContext('2d');
      ctx.drawImage(image, 0, 0);
      return Array.from(ctx.getImageData(x, y, 1, 1).data);
    },
    size: () => (image.naturalWidth ? [image.naturalWidth, image.naturalHeight] : null),
  };
}
