// An order's (or sequence's) history as openTCS records it, and the facts of an order sequence.

import { el, formatTime, propertyTable } from './dom.js';

/** openTCS's history codes, as an operator reads them. */
const EVENTS = {
  'tcs:history:orderCreated': 'created',
  'tcs:history:orderAssignedToVehicle': 'assigned to vehicle',
  'tcs:history:orderReservedForVehicle': 'reserved for vehicle',
  'tcs:history:orderDispatchingDeferred': 'waits',
  'tcs:history:orderDispatchingResumed': 'waits no longer',
  'tcs:history:orderProcVehicleChanged': 'vehicle changed',
  'tcs:history:orderFinishedDriveOrder': 'finished drive order',
  'tcs:history:orderReachedFinalState': 'final state',
  'tcs:history:sequenceCreated': 'created',
  'tcs:history:sequenceOrderAppended': 'order appended',
  'tcs:history:sequenceProcVehicleChanged': 'vehicle changed',
  'tcs:history:sequenceCompleted': 'completed',
  'tcs:history:sequenceFinished': 'finished',
};

/** The entries, oldest first: when, what (the code's name, the code itself as a tooltip) and the reason or detail. */
export function historyTable(entries) {
  if (entries.length === 0) return el('p', { className: 'muted' }, 'No history entries.');
  return el('table', { className: 'grid history', 'data-view': 'history' },
    el('thead', {}, el('tr', {}, ['Time', 'Event', 'Detail'].map((t) => el('th', {}, t)))),
    el('tbody', {}, entries.map((entry) => el('tr', {},
      el('td', { className: 'nowrap' }, formatTime(entry.timestamp)),
      el('td', { className: 'nowrap', title: entry.eventCode }, EVENTS[entry.eventCode] ?? entry.eventCode),
      el('td', { className: 'wrap' }, (entry.supplements ?? []).join('; ') || '—')))));
}

/** A sequence's facts, its orders with their states (from [orders], the live orders by name) and its history. */
export function sequenceFacts(sequence, orders) {
  return [
    propertyTable([
      ['State', sequenceState(sequence)], ['Complete', sequence.complete ? 'yes' : 'no'],
      ['Failure fatal', sequence.failureFatal ? 'yes' : 'no'],
      ['Order types', (sequence.orderTypes ?? [sequence.type]).join(', ')],
      ['Intended vehicle', sequence.intendedVehicle ?? '—'], ['Vehicle', sequence.processingVehicle ?? '—'],
      ['Created', formatTime(sequence.creationTime)], ['Finished', formatTime(sequence.finishedTime)],
    ]),
    el('h3', {}, `Orders (${sequence.orders.length})`),
    el('ol', { className: 'sequence-orders' }, sequence.orders.map((name, index) => el('li', {
      className: index <= sequence.finishedIndex ? 'done' : '',
    }, el('span', { 'data-order': name }, name), ' ',
    el('span', { className: `state ${orders?.get(name)?.state ?? ''}` }, orders?.get(name)?.state ?? 'removed')))),
    el('h3', {}, 'History'),
    historyTable(sequence.history?.entries ?? []),
  ];
}

/** finished, or how far it got: "3 of 5 orders done" (open for more while not complete). */
export function sequenceState(sequence) {
  if (sequence.finished) return 'finished';
  const done = sequence.finishedIndex + 1;
  return `${done} of ${sequence.orders.length} order${sequence.orders.length === 1 ? '' : 's'} done${sequence.complete ? '' : ', open for more'}`;
}
