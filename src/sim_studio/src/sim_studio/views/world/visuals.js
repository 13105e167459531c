// One visual of the simulator's scene (scene.py's JSON) as a three.js object in its link's
// frame. The world is Z-up, as ROS and Gazebo are (camera.up is +Z), so poses go in unchanged;
// only three's cylinder, whose axis is Y, is turned to ROS's Z.
//
// Geometries are unit-sized and shared, scaled per object; materials are shared by colour:
// fewer buffers and state changes for the GPU (here, Chromium's CPU rasteriser).

import * as THREE from '/vendor/three/build/three.module.js';
import {STLLoader} from '/vendor/three/examples/jsm/loaders/STLLoader.js';
import {ColladaLoader} from '/vendor/three/examples/jsm/loaders/ColladaLoader.js';
import {OBJLoader} from '/vendor/three/examples/jsm/loaders/OBJLoader.js';

const unitGeometries = {
  box: new THREE.BoxBufferGeometry(1, 1, 1),
  cylinder: new THREE.CylinderBufferGeometry(0.5, 0.5, 1, 32).rotateX(Math.PI / 2),
  sphere: new THREE.SphereBufferGeometry(0.5, 32, 16),
};
const materials = new Map();   // "r,g,b,a" -> material
const meshFiles = new Map();   // url -> Promise of the loaded object, cloned per visual

export function material(color) {
  const key = color.map((c) => c.toFixed(3)).join(',');
  if (!materials.has(key)) {
    const [r, g, b, a] = color;
    materials.set(key, new THREE.MeshLambertMaterial({
      color: new THREE.Color(r, g, b), transparent: a < 1, opacity: a, depthWrite: a >= 1,
    }));
  }
  return materials.get(key);
}

export function setPose(object, pose) {
  object.position.set(pose[0], pose[1], pose[2]);
  object.quaternion.set(pose[3], pose[4], pose[5], pose[6]);
}

// Collada files say which axis is up; three's loader turns a Z-up file to Y-up, and a Y-up file
// stays. In our Z-up world both then need +90 degrees about X, as Gazebo turns a Y-up file.
function loadCollada(url) {
  return new Promise((resolve, reject) => new ColladaLoader().load(url, resolve, undefined, reject));
}

function loadMesh(url, format) {
  if (!meshFiles.has(url)) {
    meshFiles.set(url, new Promise((resolve, reject) => {
      if (format === 'stl') {
        new STLLoader().load(url, (geometry) => resolve({geometry}), undefined, reject);
      } else if (format === 'obj') {
        new OBJLoader().load(url, (object) => resolve({object}), undefined, reject);
      } else if (format === 'dae') {
        loadCollada(url).then((collada) => {
          const upright = new THREE.Group();
          upright.rotation.x = Math.PI / 2;
          upright.add(collada.scene);
          resolve({object: upright, ownMaterials: true});
        }, reject);
      } else {
        reject(new Error(`no loader for .${format}`));
      }
    }));
  }
  return meshFiles.get(url);
}

// The object for one visual: a Group posed in its link, holding the drawable. Mesh files load
// in the background; the group's userData.loaded says when (the tests wait for it).
export function makeVisual(visual, onLoaded) {
  const group = new THREE.Group();
  group.name = `${visual.model}/${visual.name}`;
  group.userData = {visual: true, model: visual.model, kind: visual.type, loaded: visual.type !== 'mesh'};
  setPose(group, visual.pose);
  const [sx, sy, sz] = visual.scale;
  if (visual.type !== 'mesh') {
    const mesh = new THREE.Mesh(unitGeometries[visual.type], material(visual.color));
    mesh.scale.set(sx || 1e-6, sy || 1e-6, sz || 1e-6);
    mesh.userData.model = visual.model;
    group.add(mesh);
    return group;
  }
  group.scale.set(sx || 1, sy || 1, sz || 1);
  loadMesh(visual.mesh, visual.format).then((loaded) => {
    let drawable;
    if (loaded.geometry) {
      drawable = new THREE.Mesh(loaded.geometry, material(visual.color));
    } else {
      drawable = loaded.object.clone();
      if (!loaded.ownMaterials) drawable.traverse((o) => { if (o.isMesh) o.material = material(visual.color); });
    }
    drawable.traverse((o) => { o.userData.model = visual.model; });
    group.add(drawable);
    group.userData.loaded = true;
    onLoaded();
  }, (error) => {
    group.userData.loaded = true;
    group.userData.error = String(error && error.message || error);
    onLoaded(`${visual.model}: mesh ${visual.mesh}: ${group.userData.error}`);
  });
  return group;
}
