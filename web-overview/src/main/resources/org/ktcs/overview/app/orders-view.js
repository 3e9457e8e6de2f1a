// The live transport order table with filters; a click opens the order's details, "New order" the dialog.

import { el, fill, formatDuration, onRowPress } from './dom.js';
import { throttle } from './throttle.js';

const FINAL = new Set(['FINISHED', 'FAILED', 'UNROUTABLE', 'WITHDRAWN']);
const FILTERS = {
  all: () => true,
  open: (order) => !FINAL.has(order.state),
  FINISHED: (order) => order.state === 'FINISHED',
  FAILED: (order) => order.state === 'FAILED' || order.state === 'UNROUTABLE',
  WITHDRAWN: (order) => order.state === 'WITHDRAWN',
};
const SHOWN = 500;

export class OrdersView {
  constructor(container, { client, details, dialog }) {
    this.client = client;
    this.details = details;
    this.stateFilter = el('select', { 'aria-label': 'State filter', onchange: () => this.render() },
      el('option', { value: 'all' }, 'All states'), el('option', { value: 'open' }, 'Open'),
      el('option', { value: 'FINISHED' }, 'Finished'), el('option', { value: 'FAILED' }, 'Failed / unroutable'),
      el('option', { value: 'WITHDRAWN' }, 'Withdrawn'));
    this.textFilter = el('input', {
      type: 'search', placeholder: 'Name, vehicle or destination', 'aria-label': 'Text filter', oninput: () => this.render(),
    });
    this.count = el('span', { className: 'count' });
    this.body = el('tbody');
    onRowPress(this.body, 'data-order', (name) => this.details.show({ kind: 'order', name }));
    fill(container,
      el('div', { className: 'view-toolbar' },
        el('button', { type: 'button', className: 'primary', 'data-action': 'new-order', onclick: () => dialog.open() }, 'New order'),
        this.stateFilter, this.textFilter, this.count),
      el('table', { className: 'grid', 'data-view': 'orders' },
        el('thead', {}, el('tr', {}, ['Order', 'State', 'Vehicle', 'Destinations', 'Age'].map((t) => el('th', {}, t)))),
        this.body));
    const render = throttle(() => this.render(), 250);
    client.subscribe('transportOrders', render);
    setInterval(render, 1000);
  }

  render() {
    const text = this.textFilter.value.trim().toLowerCase();
    const matches = FILTERS[this.stateFilter.value] ?? FILTERS.all;
    const orders = this.client.objects('transportOrders')
      .filter(matches)
      .filter((order) => !text || searchText(order).includes(text))
      .sort((a, b) => Date.parse(b.creationTime) - Date.parse(a.creationTime) || b.name.localeCompare(a.name));
    this.count.textContent = `${orders.length} order${orders.length === 1 ? '' : 's'}`;
    const now = Date.now();
    fill(this.body, orders.slice(0, SHOWN).map((order) => el('tr', { 'data-order': order.name },
    el('td', { className: 'name', title: order.name }, order.name),
    el('td', { 'data-column': 'state', title: order.waitingReason ?? outcomeOf(order) ?? undefined },
      el('span', { className: `state ${order.state}` }, order.state)),
    el('td', { className: 'nowrap' }, order.processingVehicle ?? (order.intendedVehicle ? `(${order.intendedVehicle})` : '—')),
    el('td', { className: 'wrap' }, destinations(order)),
    el('td', {}, formatDuration(ageOf(order, now))))));
  }
}

/** Why a final order ended as it did, from its last history entry that says so (e.g. an UNROUTABLE order). */
export function outcomeOf(order) {
  if (!FINAL.has(order.state) || order.state === 'FINISHED') return null;
  const entries = order.history?.entries ?? [];
  const last = entries.filter((e) => (e.supplements ?? []).length > 0 && e.eventCode !== 'tcs:history:orderDispatchingDeferred').at(-1);
  return last ? last.supplements.join('; ') : null;
}

function destinations(order) {
  return order.driveOrders.map((d) => `${d.destination.destination}: ${d.destination.operation}`).join(' → ');
}

function ageOf(order, now) {
  const finished = Date.parse(order.finishedTime);
  const end = FINAL.has(order.state) && Number.isFinite(finished) && new Date(finished).getUTCFullYear() < 9000 ? finished : now;
  return end - Date.parse(order.creationTime);
}

function searchText(order) {
  return [order.name, order.processingVehicle, order.intendedVehicle, order.type, destinations(order)]
    .filter(Boolean).join(' ').toLowerCase();
}
