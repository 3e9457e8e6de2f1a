// The plant toolbar's fleet actions: find or follow a vehicle, pause or resume every vehicle at once.

import { el, fill } from './dom.js';
import { enc } from './actions.js';

export function installFleetControls(container, { ktcs, client, plant }) {
  const vehicle = el('select', { 'aria-label': 'Vehicle to find', name: 'find-vehicle' });
  const follow = el('input', { type: 'checkbox', name: 'follow', onchange: () => (follow.checked ? find() : plant.stopFollowing()) });
  const refreshChoices = () => {
    const names = client.objects('vehicles').map((v) => v.name).sort();
    const chosen = vehicle.value;
    if (names.join('\n') === [...vehicle.options].map((o) => o.value).join('\n')) return;
    fill(vehicle, names.map((name) => el('option', { value: name, selected: name === chosen }, name)));
  };
  const find = () => {
    if (!vehicle.value) return;
    if (!plant.centreOnVehicle(vehicle.value, follow.checked)) {
      ktcs.notify(`Vehicle ${vehicle.value} has no position to show.`, 'error');
    }
  };
  plant.onFollowChange = (name) => { follow.checked = Boolean(name); };
  client.subscribe('vehicles', refreshChoices);
  fill(container,
    vehicle,
    el('button', { type: 'button', 'data-action': 'find-vehicle', title: 'Centre the view on the vehicle', onclick: find }, 'Find'),
    el('label', { title: 'Keep the vehicle centred while it moves, until you pan' }, follow, ' Follow'),
    el('button', { type: 'button', 'data-action': 'pause-all', title: 'Pause every vehicle', onclick: () => setAllPaused(ktcs, client, true) }, 'Pause all'),
    el('button', { type: 'button', 'data-action': 'resume-all', title: 'Resume every paused vehicle', onclick: () => setAllPaused(ktcs, client, false) }, 'Resume all'));
}

/** Pauses (or resumes) every vehicle that is not so already; tells how many changed and which failed. */
async function setAllPaused(ktcs, client, paused) {
  const vehicles = client.objects('vehicles').filter((v) => v.paused !== paused);
  const verb = paused ? 'Paused' : 'Resumed';
  if (vehicles.length === 0) {
    ktcs.notify(`Every vehicle is ${paused ? 'paused' : 'running'} already.`, 'info');
    return;
  }
  const results = await Promise.allSettled(vehicles.map((v) =>
    ktcs.api('PUT', `/vehicles/${enc(v.name)}/paused?newValue=${paused}`)));
  const failed = results.map((r, i) => (r.status === 'rejected' ? `${vehicles[i].name}: ${r.reason.message}` : null))
    .filter(Boolean);
  const changed = vehicles.length - failed.length;
  ktcs.notify(`${verb} ${changed} vehicle${changed === 1 ? '' : 's'}.`, 'info');
  if (failed.length > 0) ktcs.notify(`${paused ? 'Pausing' : 'Resuming'} failed for ${failed.join('; ')}`, 'error');
}
