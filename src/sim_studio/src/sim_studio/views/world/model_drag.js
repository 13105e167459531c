// Selecting a model (a click on it) and moving it (TransformControls' arrows and plane, on the
// ground plane only, as Gazebo's translate tool is most often used).
//
// The arrows move a handle, not the model: the model keeps following pose_info. While the
// handle is dragged, the model is sent there a few times a second (set_model_state through the
// server's "move"); on release, once more, and the release's reply is what a drag returns.
// dragTo(model, x, y) runs the same begin / move / release steps without the mouse (the tests'
// and the benchmark's way in).

import * as THREE from '/vendor/three/build/three.module.js';
import {TransformControls} from '/vendor/three/examples/jsm/controls/TransformControls.js';

const MOVE_PERIOD_MS = 100;  // while dragging: 10 set_model_state a second is smooth enough
const CLICK_SLOP_PX = 4;     // a press and release closer than this is a click, not an orbit

export class ModelDrag {
  constructor(world, studio, say) {
    this.world = world;
    this.studio = studio;
    this.say = say;
    this.selected = null;
    this.handle = new THREE.Object3D();
    world.scene.add(this.handle);
    this.highlight = new THREE.Box3Helper(new THREE.Box3(), 0xffaa00);
    this.highlight.visible = false;
    world.scene.add(this.highlight);

    this.transform = new TransformControls(world.camera, world.renderer.domElement);
    this.transform.showZ = false;
    this.transform.setSpace('world');
    this.transform.addEventListener('change', () => { world.requestRender(); });
    this.transform.addEventListener('dragging-changed', (event) => {
      world.controls.enabled = !event.value;
      if (event.value) this.begin(); else this.release();
    });
    this.transform.addEventListener('objectChange', () => this.moving());
    world.scene.add(this.transform);

    const canvas = world.renderer.domElement;
    let down = null;
    canvas.addEventListener('mousedown', (event) => { down = {x: event.clientX, y: event.clientY}; });
    canvas.addEventListener('mouseup', (event) => {
      const from = down;
      down = null;
      if (!from || this.transform.axis !== null || this.drag) return;
      if (Math.hypot(event.clientX - from.x, event.clientY - from.y) <= CLICK_SLOP_PX) {
        this.select(world.modelAt(event.clientX, event.clientY), true);
      }
    });
    // The handle and the highlight follow the selected model as it moves.
    world.afterRender.unshift(() => this.follow());
  }

  select(model, fromHere) {
    if (model === this.selected) return;
    this.selected = model;
    if (model && this.world.models.has(model)) {
      this.transform.attach(this.handle);
      this.follow();
    } else {
      this.transform.detach();
      this.highlight.visible = false;
    }
    this.world.requestRender();
    if (fromHere) this.studio.bus.dispatchEvent(new CustomEvent('select', {detail: {model, source: 'world'}}));
  }

  follow() {
    if (!this.selected) return;
    const box = this.world.modelBox(this.selected);
    if (box.isEmpty()) return;
    if (!this.highlight.box.equals(box)) {
      this.highlight.box.copy(box);
      this.highlight.visible = true;
      this.world.requestRender();
    }
    if (!this.drag) {
      const centre = box.getCenter(new THREE.Vector3());
      this.handle.position.set(centre.x, centre.y, box.min.z);
    }
  }

  // Where the model and the handle were when the drag began: the model's own pose (its frame's
  // origin, which set_model_state sets), not its visuals' box.
  begin() {
    const model = this.selected;
    const handleStart = this.handle.position.clone();
    this.drag = {model, handleStart, lastSent: 0,
      start: this.studio.request('model_pose', {model}).then((reply) => reply.position)};
    this.drag.start.catch((error) => this.say(error.message, true));
  }

  async target() {
    const {handleStart} = this.drag;
    const start = await this.drag.start;
    return [start[0] + this.handle.position.x - handleStart.x, start[1] + this.handle.position.y - handleStart.y];
  }

  async moving() {
    if (!this.drag || performance.now() - this.drag.lastSent < MOVE_PERIOD_MS) return;
    this.drag.lastSent = performance.now();
    const [x, y] = await this.target();
    this.studio.request('move', {model: this.drag.model, x, y}).catch((error) => this.say(error.message, true));
  }

  async release() {
    if (!this.drag) return null;
    const {model} = this.drag;
    try {
      const [x, y] = await this.target();
      const reply = await this.studio.request('move', {model, x, y});
      this.say(`${model} moved to x ${x.toFixed(3)}, y ${y.toFixed(3)}`);
      return reply;
    } catch (error) {
      this.say(error.message, true);
      throw error;
    } finally {
      this.drag = null;
    }
  }

  // A drag without the mouse: select, begin, move the handle so the model lands at x, y, release.
  async dragTo(model, x, y) {
    this.select(model, true);
    this.begin();
    const start = await this.drag.start;
    this.handle.position.x = this.drag.handleStart.x + x - start[0];
    this.handle.position.y = this.drag.handleStart.y + y - start[1];
    return this.release();
  }
}
