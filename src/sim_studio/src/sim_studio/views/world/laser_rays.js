// Laser rays, as Gazebo draws a sensor's <visualize>: a line from the sensor to each beam's hit,
// in the sensor's frame (scene_info gives its pose in its link; the scan's angles turn about
// its z axis). Misses are not drawn. Only while "lasers" is ticked: the server then subscribes
// to the scan topics and sends each at most 10 times a second.

import * as THREE from '/vendor/three/build/three.module.js';
import {setPose} from './visuals.js';

const RAY_COLOUR = 0x1f5fff;

export class LaserRays {
  constructor(world) {
    this.world = world;
    this.sensors = new Map();  // topic -> LineSegments in its link
    this.visible = false;
  }

  setScene(scene) {
    for (const lines of this.sensors.values()) lines.parent && lines.parent.remove(lines);
    this.sensors.clear();
    for (const sensor of scene.sensors) {
      if (sensor.kind !== 'laser') continue;
      const lines = new THREE.LineSegments(new THREE.BufferGeometry(),
          new THREE.LineBasicMaterial({color: RAY_COLOUR, transparent: true, opacity: 0.6}));
      lines.userData.ray = true;
      setPose(lines, sensor.pose);
      lines.visible = this.visible;
      lines.frustumCulled = false;
      this.world.link(sensor.frame).add(lines);
      this.sensors.set(sensor.topic, lines);
    }
  }

  show(on) {
    this.visible = on;
    for (const lines of this.sensors.values()) lines.visible = on;
    this.world.requestRender();
  }

  setScan(scan) {
    const lines = this.sensors.get(scan.topic);
    if (!lines) return;
    const points = [];
    scan.ranges.forEach((range, i) => {
      if (range == null) return;
      const angle = scan.angle_min + i * scan.angle_increment;
      points.push(0, 0, 0, range * Math.cos(angle), range * Math.sin(angle), 0);
    });
    lines.geometry.setAttribute('position', new THREE.Float32BufferAttribute(points, 3));
    lines.geometry.computeBoundingSphere();
    this.world.requestRender();
  }
}
