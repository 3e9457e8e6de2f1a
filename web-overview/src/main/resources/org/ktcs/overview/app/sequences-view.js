// The order sequences: one row per sequence, live; a click opens its details with its orders and history.

import { el, fill, onRowPress } from './dom.js';
import { throttle } from './throttle.js';
import { sequenceState } from './order-history.js';

const HEADINGS = [
  ['Sequence'], ['Progress'], ['Vehicle'], ['Complete', 'Complete: no more orders can be appended'],
  ['Fatal', 'Failure fatal: a failed order fails the orders after it'],
];

export class SequencesView {
  constructor(container, { client, details }) {
    this.client = client;
    this.body = el('tbody');
    this.count = el('span', { className: 'count' });
    onRowPress(this.body, 'data-sequence', (name) => details.show({ kind: 'sequence', name }));
    fill(container,
      el('div', { className: 'view-toolbar' }, this.count),
      el('table', { className: 'grid', 'data-view': 'sequences' },
        el('thead', {}, el('tr', {}, HEADINGS.map(([text, title]) => el('th', { title }, text)))),
        this.body));
    const render = throttle(() => this.render(), 250);
    client.subscribe('orderSequences', render);
    client.subscribe('transportOrders', render);
  }

  render() {
    const sequences = this.client.objects('orderSequences')
      .sort((a, b) => Date.parse(b.creationTime) - Date.parse(a.creationTime) || a.name.localeCompare(b.name));
    this.count.textContent = `${sequences.length} sequence${sequences.length === 1 ? '' : 's'}`;
    fill(this.body, sequences.map((sequence) => el('tr', { 'data-sequence': sequence.name },
      el('td', { className: 'name', title: sequence.name }, sequence.name),
      el('td', {}, sequenceState(sequence)),
      el('td', { className: 'nowrap' }, sequence.processingVehicle ?? (sequence.intendedVehicle ? `(${sequence.intendedVehicle})` : '—')),
      el('td', {}, sequence.complete ? 'yes' : 'no'),
      el('td', {}, sequence.failureFatal ? 'yes' : 'no'))));
  }
}
