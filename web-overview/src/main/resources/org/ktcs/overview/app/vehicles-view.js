// The vehicle list: one row per vehicle, live; a click opens its details and actions.

import { el, fill, onRowPress } from './dom.js';
import { throttle } from './throttle.js';

export class VehiclesView {
  constructor(container, { client, details }) {
    this.details = details;
    this.client = client;
    this.body = el('tbody');
    onRowPress(this.body, 'data-vehicle', (name) => this.details.show({ kind: 'vehicle', name }));
    fill(container, el('table', { className: 'grid', 'data-view': 'vehicles' },
      el('thead', {}, el('tr', {}, ['Vehicle', 'State', 'Processing', 'Integration', 'Energy', 'Position', 'Order']
        .map((title) => el('th', {}, title)))),
      this.body));
    const render = throttle(() => this.render(), 250);
    client.subscribe('vehicles', render);
  }

  render() {
    const vehicles = this.client.objects('vehicles').sort((a, b) => a.name.localeCompare(b.name));
    fill(this.body, vehicles.map((vehicle) => el('tr', { 'data-vehicle': vehicle.name },
    el('td', { className: 'nowrap' }, vehicle.name, vehicle.paused ? el('span', { className: 'tag' }, 'paused') : null),
    el('td', {}, el('span', { className: `state ${vehicle.state?.state}` }, vehicle.state?.state)),
    el('td', {}, vehicle.procState?.procState),
    el('td', {}, vehicle.integrationLevel.replace('TO_BE_', '').toLowerCase()),
    el('td', {}, `${vehicle.energyLevel}%`),
    el('td', {}, vehicle.currentPosition ?? '—'),
    el('td', {}, vehicle.transportOrder ?? '—'))));
  }
}
