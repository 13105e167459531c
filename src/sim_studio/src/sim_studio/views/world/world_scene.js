// The 3D scene: renderer, camera, orbit controls, lights, grid and ground, one Object3D per
// link (named "model::link", placed in the world by pose_info) holding its visuals.
//
// It draws only when something changed (poses, the camera, a mesh loaded: requestRender()), so
// a still world costs the machine nothing; `continuous` draws every animation frame (the
// benchmark's capacity measure).

import * as THREE from '/vendor/three/build/three.module.js';
import {OrbitControls} from '/vendor/three/examples/jsm/controls/OrbitControls.js';
import {makeVisual, setPose} from './visuals.js';

const GROUND_SIZE = 200;
const MAX_PIXEL_RATIO = 2;
// On a CPU renderer the frame's cost is its pixels: 3/4 of a pixel per CSS pixel (0.56 of the
// pixels, slightly soft) took a frame of the maze from 17 to 11 ms of CPU.
const SOFTWARE_PIXEL_RATIO = 0.75;

// Whether WebGL runs on the CPU (Chromium's SwiftShader, Mesa's llvmpipe: a headless machine, a
// remote desktop). There every pixel costs: no antialiasing (4 samples a pixel) and fewer pixels.
function softwareRenderer() {
  const gl = document.createElement('canvas').getContext('webgl');
  if (!gl) return true;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = info ? String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL)) : '';
  const lose = gl.getExtension('WEBGL_lose_context');
  if (lose) lose.loseContext();  // give the probe's context back at once
  return /swiftshader|llvmpipe|software/i.test(name);
}

export class WorldScene {
  constructor(container, onError) {
    this.container = container;
    this.onError = onError;
    const software = softwareRenderer();
    this.software = software;
    // Opaque, no stencil: the compositor need not blend the canvas, nor the renderer keep a buffer it never uses.
    this.renderer = new THREE.WebGLRenderer({antialias: !software, alpha: false, stencil: false});
    this.renderer.setPixelRatio(software ? SOFTWARE_PIXEL_RATIO : Math.min(window.devicePixelRatio || 1, MAX_PIXEL_RATIO));
    this.renderer.setClearColor(0xc9d6e3);
    container.appendChild(this.renderer.domElement);

    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(50, 1, 0.02, 1000);
    this.camera.up.set(0, 0, 1);
    this.camera.position.set(5, -5, 3);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.requestRender());

    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x606060, 0.75));
    const sun = new THREE.DirectionalLight(0xffffff, 0.6);
    sun.position.set(3, -5, 10);
    this.scene.add(sun);
    const grid = new THREE.GridHelper(20, 20, 0x7a7a7a, 0x9a9a9a);
    grid.rotation.x = Math.PI / 2;  // three's grid lies in XZ; ours in XY
    grid.position.z = 0.002;
    this.scene.add(grid);
    const ground = new THREE.Mesh(new THREE.PlaneBufferGeometry(GROUND_SIZE, GROUND_SIZE),
        new THREE.MeshLambertMaterial({color: 0xb5b5b0}));
    ground.position.z = -0.003;
    this.scene.add(ground);
    this.ground = ground;

    this.links = new Map();      // "model::link" -> Object3D
    this.indexed = [];           // pose_info's order -> Object3D
    this.models = new Map();     // model -> [link Object3D]
    this.visualCount = 0;
    this.continuous = false;
    this.afterRender = [];       // callbacks(timestamp) after each drawn frame
    this.stats = {renders: 0, poseFrames: 0};
    this.fitted = false;
    this.scheduled = false;

    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  // A frame is asked for only when something changed: a page whose world stands still asks the
  // browser for no animation frames at all (each one wakes its compositor; 0.2 cores idle here).
  requestRender() {
    if (this.scheduled) return;
    this.scheduled = true;
    requestAnimationFrame(() => this.draw());
  }

  draw() {
    this.scheduled = false;
    this.renderer.render(this.scene, this.camera);
    this.stats.renders += 1;
    const now = performance.timeOrigin + performance.now();
    for (const callback of this.afterRender) callback(now);
    if (this.continuous) this.requestRender();
  }

  setContinuous(on) {
    this.continuous = on;
    this.requestRender();
  }

  resize() {
    const width = Math.max(1, this.container.clientWidth);
    const height = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(width, height);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }

  link(name) {
    if (!this.links.has(name)) {
      const object = new THREE.Group();
      object.name = name;
      object.visible = false;  // until pose_info places it
      this.scene.add(object);
      this.links.set(name, object);
    }
    return this.links.get(name);
  }

  // A new scene: every link's visuals built again; links the scene no longer has go. Link
  // objects that stay keep their poses (pose_info sends only what moved).
  setScene(scene) {
    const frames = new Set(scene.visuals.map((v) => v.frame).concat(scene.sensors.map((s) => s.frame)));
    for (const [name, object] of this.links) {
      object.children.filter((c) => c.userData.visual).forEach((c) => object.remove(c));
      if (!frames.has(name) && !this.indexed.includes(object)) {
        this.scene.remove(object);
        this.links.delete(name);
      }
    }
    this.models.clear();
    for (const visual of scene.visuals) {
      const link = this.link(visual.frame);
      link.userData.model = visual.model;
      link.add(makeVisual(visual, (error) => {
        if (error) this.onError(error);
        this.requestRender();
      }));
    }
    for (const [name, object] of this.links) {
      const model = name.split('::')[0];
      if (!this.models.has(model)) this.models.set(model, []);
      this.models.get(model).push(object);
    }
    this.visualCount = scene.visuals.length;
    // The ground plane drawn here only where the world has none of its own: every pixel of a
    // second ground costs a frame on a CPU renderer.
    this.ground.visible = !scene.visuals.some((v) => v.type === 'box' && v.scale[0] >= 50 && v.scale[1] >= 50);
    this.requestRender();
  }

  // A "poses" message: names (when they changed) and [index, x, y, z, qx, qy, qz, qw, ...].
  applyPoses(message) {
    if (message.names) {
      this.indexed = message.names.map((name) => this.link(name));
      for (const [name, object] of this.links) {
        if (!message.names.includes(name)) object.visible = false;
      }
    }
    const p = message.poses;
    for (let k = 0; k + 7 < p.length; k += 8) {
      const object = this.indexed[p[k]];
      if (!object) continue;
      object.position.set(p[k + 1], p[k + 2], p[k + 3]);
      object.quaternion.set(p[k + 4], p[k + 5], p[k + 6], p[k + 7]);
      object.visible = true;
    }
    this.stats.poseFrames += 1;
    this.posesAppliedAt = performance.timeOrigin + performance.now();  // for the latency's breakdown
    this.requestRender();
    if (!this.fitted && this.visualCount > 0) this.fit();
  }

  // The first view: the camera looks at what the world holds (the ground aside), from the
  // south-east and above, as Gazebo's default camera does.
  fit() {
    const box = new THREE.Box3();
    for (const object of this.links.values()) {
      if (!object.visible) continue;
      const b = new THREE.Box3().setFromObject(object);
      if (!b.isEmpty() && b.getSize(new THREE.Vector3()).length() < 50) box.union(b);
    }
    if (box.isEmpty()) return;
    this.fitted = true;
    const centre = box.getCenter(new THREE.Vector3());
    const size = Math.max(1.0, box.getSize(new THREE.Vector3()).length());
    this.controls.target.copy(centre);
    this.camera.position.copy(centre).add(new THREE.Vector3(0.9, -1.15, 0.7).multiplyScalar(size));
    this.controls.update();
  }

  modelBox(model) {
    const box = new THREE.Box3();
    for (const object of this.models.get(model) || []) box.union(new THREE.Box3().setFromObject(object));
    return box;
  }

  // The model under a pixel of the canvas, or null.
  modelAt(clientX, clientY) {
    const rect = this.renderer.domElement.getBoundingClientRect();
    const pointer = new THREE.Vector2(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    const raycaster = new THREE.Raycaster();
    raycaster.setFromCamera(pointer, this.camera);
    const hits = raycaster.intersectObjects([...this.links.values()].filter((o) => o.visible), true);
    const hit = hits.find((h) => h.object.userData.model);
    return hit ? hit.object.userData.model : null;
  }
}
