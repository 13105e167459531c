// World: the simulator's models in 3D with Gazebo's toolbar. The server sends the scene (every
// visual in its link's frame) when models come or go, and the links' poses one frame at a time:
// the page asks for the next frame once it has drawn the last, so it never falls behind.
// On a CPU renderer it asks at most 30 times a second (a moving world's frames cost the cores
// the simulator runs on); `?fps=N` in the URL sets that cap (0: every animation frame).
//
// window.studio.world is the way in for tests and the benchmark: visualCount(), meshesLoaded(),
// dragTo(model, x, y), select(model), whenAt(link, x, y, tolerance), stats(), setContinuous(on).

import {WorldScene} from './world_scene.js';
import {ModelDrag} from './model_drag.js';
import {LaserRays} from './laser_rays.js';
import {Toolbar} from './toolbar.js';

const CENTRE_PERIOD_MS = 250;
const SOFTWARE_MAX_FPS = 30;

// Pose frames a second the page asks for at most: ?fps=N, else 30 on a CPU renderer, else no cap.
function maxFrameRate(software) {
  const asked = Number.parseFloat(new URLSearchParams(location.search).get('fps'));
  if (Number.isFinite(asked) && asked >= 0) return asked;
  return software ? SOFTWARE_MAX_FPS : 0;
}

export default function mount(root, studio) {
  const style = document.createElement('link');
  style.rel = 'stylesheet';
  style.href = '/views/world/world.css';
  document.head.appendChild(style);

  const status = document.createElement('div');
  status.className = 'world-status';
  status.id = 'world-status';
  const say = (text, isError = false) => {
    status.textContent = text;
    status.classList.toggle('error', isError);
    if (isError) studio.status(`world: ${text}`, true);
  };
  const canvasBox = document.createElement('div');
  canvasBox.className = 'world-canvas';
  const world = new WorldScene(canvasBox, (error) => say(error, true));
  const rays = new LaserRays(world);
  const toolbar = new Toolbar(studio, say, (on) => rays.show(on));
  const drag = new ModelDrag(world, studio, say);
  root.append(toolbar.element, canvasBox, status);

  let scene = null;
  studio.on('scene', (message) => {
    scene = message;
    world.setScene(message);
    rays.setScene(message);
    drag.select(drag.selected, false);  // re-attach: the model may have been spawned again
  });

  // Poses: apply, and ask for the next frame once this one is on screen (and the cap allows).
  const minPeriodMs = maxFrameRate(world.software) > 0 ? 1000 / maxFrameRate(world.software) : 0;
  let frameDrawn = null;
  let lastAsk = -Infinity;
  studio.on('poses', (message) => {
    world.applyPoses(message);
    frameDrawn = () => {
      lastAsk = performance.now();
      studio.send('frame');
    };
  });
  world.afterRender.push(() => {
    if (frameDrawn) {
      const ask = frameDrawn;
      frameDrawn = null;
      const wait = lastAsk + minPeriodMs - performance.now();
      if (wait > 1) setTimeout(ask, wait);
      else ask();
    }
  });
  studio.on('scan', (message) => rays.setScan(message));

  studio.bus.addEventListener('select', (event) => {
    if (event.detail.source !== 'world') drag.select(event.detail.model, false);
  });

  // Where the camera looks: the Models view inserts there when no position is given.
  let lastCentre = 0;
  world.controls.addEventListener('change', () => {
    if (performance.now() - lastCentre < CENTRE_PERIOD_MS) return;
    lastCentre = performance.now();
    const t = world.controls.target;
    studio.bus.dispatchEvent(new CustomEvent('view-centre', {detail: {x: t.x, y: t.y, z: t.z}}));
  });

  // Latency: when a link is first drawn within `tolerance` of (x, y), and when the poses that
  // put it there arrived; wall-clock milliseconds.
  const watches = [];
  world.afterRender.push((now) => {
    for (let i = watches.length - 1; i >= 0; i -= 1) {
      const {link, x, y, tolerance, resolve} = watches[i];
      const object = world.links.get(link);
      if (object && object.visible && Math.hypot(object.position.x - x, object.position.y - y) <= tolerance) {
        watches.splice(i, 1);
        resolve({drawn: now, arrived: world.posesAppliedAt});
      }
    }
  });

  window.studio = window.studio || {};
  window.studio.world = {
    visualCount: () => world.visualCount,
    visualObjects: () => {
      let n = 0;
      world.scene.traverse((o) => { if (o.userData.visual) n += 1; });
      return n;
    },
    meshesLoaded: () => {
      let ok = true;
      world.scene.traverse((o) => { if (o.userData.visual && !o.userData.loaded) ok = false; });
      return ok;
    },
    scene: () => scene,
    linkPosition: (link) => {
      const o = world.links.get(link);
      return o && o.visible ? [o.position.x, o.position.y, o.position.z] : null;
    },
    rayCount: () => {
      let n = 0;
      for (const lines of rays.sensors.values()) {
        const position = lines.geometry.getAttribute('position');
        if (lines.visible && position) n += position.count / 2;
      }
      return n;
    },
    select: (model) => drag.select(model, true),
    selected: () => drag.selected,
    dragTo: (model, x, y) => drag.dragTo(model, x, y),
    whenAt: (link, x, y, tolerance = 0.001) => new Promise((resolve) => watches.push({link, x, y, tolerance, resolve})),
    stats: () => ({...world.stats, at: performance.now()}),
    maxFrameRate: () => maxFrameRate(world.software),
    setContinuous: (on) => world.setContinuous(on),
    scene3d: () => world,  // the WorldScene itself, for experiments from the console
    screenPosition: (model) => {
      const box = world.modelBox(model);
      if (box.isEmpty()) return null;
      const centre = box.getCenter(new box.min.constructor()).project(world.camera);
      const rect = world.renderer.domElement.getBoundingClientRect();
      return [rect.left + (centre.x + 1) / 2 * rect.width, rect.top + (1 - centre.y) / 2 * rect.height];
    },
  };
}
