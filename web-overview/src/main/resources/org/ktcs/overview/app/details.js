// The detail panel for whatever the operator clicked: point, path, location, vehicle or transport order. The facts
// refresh live; the actions stay put, so typing is never interrupted.

import { el, fill, formatTime, propertyTable } from './dom.js';
import { outcomeOf } from './orders-view.js';
import { act, enc } from './actions.js';
import { vehicleActions } from './vehicle-actions.js';
import { operatorActions } from './operator-actions.js';
import { historyTable, sequenceFacts } from './order-history.js';
import { driverPanel } from './driver-panel.js';

export class Details {
  constructor(container, { ktcs, client }) {
    this.container = container;
    this.ktcs = ktcs;
    this.client = client;
    this.plant = null;
    this.selection = null;
    // An order named in the details (a sequence's orders) opens that order's details.
    container.addEventListener('click', (event) => {
      const order = event.target.closest?.('[data-order]')?.getAttribute('data-order');
      if (order) this.show({ kind: 'order', name: order });
    });
  }

  show(selection) {
    // A target being picked for "send vehicle to" takes the next point or location clicked, not the details.
    if (this.pick && (selection?.kind === 'point' || selection?.kind === 'location')) {
      const pick = this.pick;
      this.pick = null;
      pick(selection);
      return;
    }
    this.pick = null;
    this.selection = selection;
    this.plant?.select(selection);
    this.plant?.highlightRoute(selection?.kind === 'order' ? this.orderPaths(selection.name) : []);
    if (!selection) {
      this.driverPanel?.close();
      this.driverPanel = null;
      this.container.hidden = true;
      return;
    }
    // The vehicle's driver panel (e.g. the simulated vehicle's position, energy, load) sits right under the title.
    this.driverPanel?.close();
    this.driverPanel = selection?.kind === 'vehicle' ? driverPanel(this.ktcs, this.plant, selection.name) : null;
    this.info = el('div', { className: 'details-info' });
    this.actions = el('div', { className: 'details-actions' }, this.actionsFor(selection));
    fill(this.container,
      el('header', {},
        el('h2', {}, `${kindTitle(selection.kind)} ${selection.name}`),
        el('button', { type: 'button', className: 'close', title: 'Close', onclick: () => this.show(null) }, '×')),
      this.driverPanel?.element, this.info, this.actions);
    this.container.hidden = false;
    this.refresh();
  }

  refresh() {
    const selection = this.selection;
    if (!selection) return;
    const object = this.objectOf(selection);
    if (!object) {
      fill(this.info, el('p', {}, 'No longer exists.'));
      return;
    }
    fill(this.info, this.factsOf(selection.kind, object));
    if (selection.kind === 'order') this.plant?.highlightRoute(this.orderPaths(selection.name));
  }

  objectOf({ kind, name }) {
    const model = this.ktcs.model();
    if (kind === 'vehicle') return this.client.state.get('vehicles')?.get(name);
    if (kind === 'order') return this.client.state.get('transportOrders')?.get(name);
    if (kind === 'sequence') return this.client.state.get('orderSequences')?.get(name);
    if (!model) return null;
    const list = { point: model.points, path: model.paths, location: model.locations }[kind] ?? [];
    return list.find((element) => element.name === name);
  }

  orderPaths(name) {
    const order = this.client.state.get('transportOrders')?.get(name);
    return (order?.driveOrders ?? []).flatMap((d) => d.route?.steps ?? []).map((s) => s.path).filter(Boolean);
  }

  factsOf(kind, object) {
    const block = (name) => (this.ktcs.model()?.blocks ?? []).filter((b) => b.memberNames.includes(name))
      .map((b) => `${b.name} (${b.type})`).join(', ') || '—';
    switch (kind) {
      case 'point':
        return [propertyTable([
          ['Type', object.type], ['Position', `${object.position.x}, ${object.position.y} mm`],
          ['Layer', object.layout?.layerId], ['Blocks', block(object.name)],
        ]), properties(object.properties)];
      case 'path':
        return [propertyTable([
          ['From', object.srcPointName], ['To', object.destPointName], ['Length', `${object.length} mm`],
          ['Max. velocity', `${object.maxVelocity} / reverse ${object.maxReverseVelocity} mm/s`],
          ['Locked', object.locked ? 'yes' : 'no'], ['Blocks', block(object.name)],
        ]), properties(object.properties)];
      case 'location': {
        const type = this.ktcs.model()?.locationTypes.find((t) => t.name === object.typeName);
        return [propertyTable([
          ['Type', object.typeName], ['Operations', (type?.allowedOperations ?? []).join(', ') || '—'],
          ['Links', object.links.map((l) => l.pointName).join(', ') || '—'],
          ['Locked', object.locked ? 'yes' : 'no'], ['Position', `${object.position.x}, ${object.position.y} mm`],
        ]), properties(object.properties)];
      }
      case 'vehicle':
        return vehicleFacts(object);
      case 'order':
        return orderFacts(object);
      case 'sequence':
        return sequenceFacts(object, this.client.state.get('transportOrders'));
      default:
        return [];
    }
  }

  actionsFor({ kind, name }) {
    if (kind === 'path' || kind === 'location') {
      const resource = kind === 'path' ? 'paths' : 'locations';
      const setLocked = (locked) => act(this.ktcs, `${locked ? 'Lock' : 'Unlock'} ${kind} ${name}`,
        () => this.ktcs.api('PUT', `/${resource}/${enc(name)}/locked?newValue=${locked}`));
      return [
        el('button', { type: 'button', 'data-action': 'lock', onclick: () => setLocked(true) }, 'Lock'),
        el('button', { type: 'button', 'data-action': 'unlock', onclick: () => setLocked(false) }, 'Unlock'),
      ];
    }
    if (kind === 'vehicle') {
      const vehicle = this.objectOf({ kind, name });
      return [...vehicleActions(this.ktcs, name, vehicle?.integrationLevel),
        ...operatorActions(this.ktcs, name, vehicle, (pick) => { this.pick = pick; })];
    }
    if (kind === 'order') {
      if (FINAL.has(this.objectOf({ kind, name })?.state)) return [];
      const withdraw = (immediate) => act(this.ktcs, `Withdraw ${name}${immediate ? ' immediately' : ''}`,
        () => this.ktcs.api('POST', `/transportOrders/${enc(name)}/withdrawal?immediate=${immediate}`));
      return [
        el('button', { type: 'button', onclick: () => withdraw(false) }, 'Withdraw'),
        el('button', { type: 'button', className: 'danger', onclick: () => withdraw(true) }, 'Withdraw immediately'),
      ];
    }
    return [];
  }
}

function kindTitle(kind) {
  return { point: 'Point', path: 'Path', location: 'Location', vehicle: 'Vehicle', order: 'Order', sequence: 'Order sequence' }[kind] ?? kind;
}

function properties(list) {
  const entries = Array.isArray(list) ? list.map((p) => [p.name ?? p.key, p.value]) : Object.entries(list ?? {});
  if (entries.length === 0) return null;
  return [el('h3', {}, 'Properties'), propertyTable(entries)];
}

function resources(sets) {
  const names = [...new Set((sets ?? []).flat())];
  return names.length === 0 ? '—' : names.join(', ');
}

function vehicleFacts(vehicle) {
  const pose = vehicle.pose?.position;
  return [propertyTable([
    ['State', vehicle.state?.state], ['Processing', vehicle.procState?.procState],
    ...(vehicle.waitingReason ? [['Takes no orders because', vehicle.waitingReason]] : []),
    ['Integration', vehicle.integrationLevel], ['Paused', vehicle.paused ? 'yes' : 'no'],
    ['Energy', `${vehicle.energyLevel}%`], ['Position', vehicle.currentPosition ?? '—'],
    ['Precise position', pose ? `${pose.x}, ${pose.y} mm` : '—'],
    ['Orientation', typeof vehicle.pose?.orientationAngle === 'number' ? `${vehicle.pose.orientationAngle}°` : '—'],
    ['Load', (vehicle.loadHandlingDevices ?? []).map((d) => `${d.label}: ${d.full ? 'full' : 'empty'}`).join(', ') || '—'],
    ['Transport order', vehicle.transportOrder ?? '—'], ['Order sequence', vehicle.orderSequence ?? '—'],
    ['Allocated', resources(vehicle.allocatedResources)], ['Claimed', resources(vehicle.claimedResources)],
  ]), properties(vehicle.properties)];
}

const FINAL = new Set(['FINISHED', 'FAILED', 'UNROUTABLE', 'WITHDRAWN']);

function orderFacts(order) {
  const final = FINAL.has(order.state);
  const why = order.waitingReason ? [['Waiting because', order.waitingReason]]
    : outcomeOf(order) ? [['Reason', outcomeOf(order)]] : [];
  return [
    propertyTable([
      ['State', order.state], ...why, ['Vehicle', order.processingVehicle ?? '—'],
      ['Intended vehicle', order.intendedVehicle ?? '—'], ['Type', order.type],
      ['Created', formatTime(order.creationTime)], ['Deadline', formatTime(order.deadline)],
      ['Finished', formatTime(order.finishedTime)], ['Sequence', order.wrappingSequence ?? '—'],
    ]),
    el('h3', {}, 'Drive orders'),
    el('ol', { className: 'drive-orders' }, order.driveOrders.map((driveOrder, index) => el('li', {
      className: index === order.currentDriveOrderIndex ? 'current' : '',
    },
    el('div', {}, el('strong', {}, `${driveOrder.destination.destination}`), ` · ${driveOrder.destination.operation} · `,
      el('span', { className: `state ${driveOrder.state}` }, driveOrder.state)),
    el('div', { className: 'route' }, driveOrder.route
      ? `Route: ${driveOrder.route.steps.map((s) => s.destinationPoint).join(' → ')} (costs ${driveOrder.route.costs})`
      : (final ? 'Route: none (the order ended before it was routed)' : 'Route: not yet computed'))))),
    el('h3', {}, 'History'),
    historyTable(order.history?.entries ?? []),
    properties(order.properties),
  ];
}
