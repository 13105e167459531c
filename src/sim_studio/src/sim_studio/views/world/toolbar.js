// Gazebo's toolbar and status bar in one row above the world: play / pause, step, sim time,
// the real-time factor (measured) and its target, reset world, reset time, and the lasers tick.
import {element} from '/dom.js';


// Gazebo's icons as inline SVG: the play / pause / step glyphs are missing from many fonts.
const ICONS = {
  play: '<svg viewBox="0 0 16 16" width="14" height="14"><path d="M4 2l10 6-10 6z" fill="currentColor"/></svg>',
  pause: '<svg viewBox="0 0 16 16" width="14" height="14"><path d="M3 2h4v12H3zM9 2h4v12H9z" fill="currentColor"/></svg>',
  step: '<svg viewBox="0 0 16 16" width="14" height="14"><path d="M2 2l8 6-8 6zM11 2h3v12h-3z" fill="currentColor"/></svg>',
};

function icon(button, name) {
  button.innerHTML = ICONS[name];  // our own constant markup, never text from ROS
}

export function formatSimTime(seconds) {
  const whole = Math.floor(seconds);
  const pad = (n, width = 2) => String(n).padStart(width, '0');
  const ms = Math.floor((seconds - whole) * 1000);
  return `${pad(Math.floor(whole / 3600))}:${pad(Math.floor(whole / 60) % 60)}:${pad(whole % 60)}.${pad(ms, 3)}`;
}

export class Toolbar {
  constructor(studio, say, onLasers) {
    this.studio = studio;
    this.say = say;
    this.playPause = element('button', {id: 'world-playpause', title: 'Pause'});
    this.step = element('button', {id: 'world-step', title: 'Step (while paused)'});
    icon(this.playPause, 'pause');
    icon(this.step, 'step');
    this.simTime = element('span', {id: 'world-simtime', class: 'value', text: '–'});
    this.rtf = element('span', {id: 'world-rtf', class: 'value', text: '–'});
    this.target = element('input', {id: 'world-target', type: 'text', size: '4', title: 'real-time factor target; 0: as fast as possible'});
    this.resetWorld = element('button', {id: 'world-reset-world', text: 'Reset world'});
    this.resetTime = element('button', {id: 'world-reset-time', text: 'Reset time'});
    this.lasers = element('input', {id: 'world-lasers', type: 'checkbox'});
    this.element = element('div', {class: 'world-toolbar'},
        this.playPause, this.step,
        element('span', {class: 'field'}, 'Sim time ', this.simTime),
        element('span', {class: 'field', title: 'real-time factor: sim time / wall time over the last second'}, 'RTF ', this.rtf),
        element('label', {class: 'field', title: 'real-time factor target; 0: as fast as possible'}, 'target ', this.target),
        this.resetWorld, this.resetTime,
        element('label', {class: 'field'}, this.lasers, ' lasers'));
    this.paused = null;

    this.playPause.addEventListener('click', () => this.command(this.paused ? 'play' : 'pause'));
    this.step.addEventListener('click', () => this.command('step'));
    this.resetWorld.addEventListener('click', () => this.command('reset_world'));
    this.resetTime.addEventListener('click', () => this.command('reset_time'));
    // While the user edits the target, the status does not overwrite it.
    this.editing = false;
    this.target.addEventListener('input', () => { this.editing = true; });
    this.target.addEventListener('change', () => {
      this.editing = false;
      if (this.target.value.trim() !== '') this.command('target', {rtf: this.target.value});
    });
    this.lasers.addEventListener('change', () => {
      onLasers(this.lasers.checked);
      this.command('lasers', {on: this.lasers.checked});
    });
    studio.on('status', (status) => this.show(status));
  }

  async command(type, fields = {}) {
    try {
      const reply = await this.studio.request(type, fields);
      if (type === 'step') this.say(`stepped to ${reply.sim_time.toFixed(3)} s`);
      if (type === 'target') this.say(`real-time factor target ${Number(fields.rtf) || 'unlimited'}`);
    } catch (error) {
      this.say(error.message, true);
    }
  }

  show(status) {
    if (status.error) {
      this.simTime.textContent = '–';
      this.rtf.textContent = '–';
      this.say(status.error, true);
      return;
    }
    this.paused = status.paused;
    if (this.playPause.dataset.paused !== String(status.paused)) icon(this.playPause, status.paused ? 'play' : 'pause');
    this.playPause.title = status.paused ? 'Play' : 'Pause';
    this.playPause.dataset.paused = String(status.paused);  // after icon(): it compares with the old value
    this.step.disabled = !status.paused;
    this.simTime.textContent = formatSimTime(status.sim_time);
    this.simTime.dataset.seconds = String(status.sim_time);
    this.rtf.textContent = status.rtf == null ? (status.paused ? 'paused' : '–') : status.rtf.toFixed(2);
    if (!this.editing && document.activeElement !== this.target) {
      this.target.value = status.target > 0 ? String(+status.target.toFixed(3)) : '0';
    }
  }
}
