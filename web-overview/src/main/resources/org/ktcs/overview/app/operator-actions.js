// The operator actions of openTCS's Operations Desk for one vehicle: reroute, send it somewhere, edit its energy
// thresholds and acceptable order types, choose its driver. Each goes through the web API; its result is shown.

import { el, fill } from './dom.js';
import { act, enc } from './actions.js';
import { operationsFor, targetOptions } from './order-dialog.js';

const THRESHOLDS = [
  ['energyLevelCritical', 'Critical'], ['energyLevelGood', 'Good'],
  ['energyLevelSufficientlyRecharged', 'Sufficiently recharged'], ['energyLevelFullyRecharged', 'Fully recharged'],
];

/**
 * The rows of operator actions for vehicle [name]. [pickTarget] lets the operator choose a point or location by
 * clicking it in the plant view: it calls back with `{ kind, name }` once.
 */
export function operatorActions(ktcs, name, vehicle, pickTarget) {
  const path = `/vehicles/${enc(name)}`;
  const run = (label, method, suffix, body) => act(ktcs, `${label} (${name})`, () => ktcs.api(method, `${path}${suffix}`, body));
  return [
    el('div', { className: 'action-row' },
      el('button', { type: 'button', 'data-action': 'reroute', title: 'New route from where the commands already sent end', onclick: () => run('Reroute', 'POST', '/rerouteRequest?forced=false') }, 'Reroute'),
      el('button', { type: 'button', 'data-action': 'reroute-forced', className: 'danger', title: 'New route from where the vehicle stands; only for a vehicle that stands still', onclick: () => run('Forced reroute', 'POST', '/rerouteRequest?forced=true') }, 'Reroute (forced)')),
    sendTo(ktcs, name, pickTarget),
    thresholds(ktcs, name, run, vehicle),
    orderTypes(run, vehicle),
    driverChoice(ktcs, run, path),
  ];
}

function sendTo(ktcs, vehicle, pickTarget) {
  const model = ktcs.model();
  const operations = el('select', { 'aria-label': 'Operation', name: 'send-operation' });
  const target = el('select', { 'aria-label': 'Send to', name: 'send-target', onchange: () => fillOperations() },
    model ? targetOptions(model) : []);
  // NOP ("just drive there") is allowed at every location, as in openTCS; it comes first for a location.
  const offered = () => {
    const allowed = model ? operationsFor(model, target.value) : [];
    return target.value.startsWith('location:') ? ['NOP', ...allowed.filter((op) => op !== 'NOP')] : allowed;
  };
  const fillOperations = () => fill(operations, offered().map((op) => el('option', { value: op }, op)));
  fillOperations();
  const pick = () => {
    ktcs.notify('Click a point or location in the plant to send the vehicle there.', 'info');
    pickTarget((picked) => {
      target.value = `${picked.kind}:${picked.name}`;
      fillOperations();
    });
  };
  const send = () => act(ktcs, `Send ${vehicle} to ${target.value.replace(/^\w+:/, '')}`, async () => {
    if (!operations.value) throw new Error('the target offers no operation');
    const body = {
      incompleteName: true,
      intendedVehicle: vehicle,
      destinations: [{ locationName: target.value.replace(/^(location|point):/, ''), operation: operations.value }],
    };
    return ktcs.api('POST', '/transportOrders/Send-', body);
  });
  return el('div', { className: 'action-row' }, el('span', { className: 'action-label' }, 'Send to'), target, operations,
    el('button', { type: 'button', 'data-action': 'pick-target', title: 'Choose the target in the plant view', onclick: pick }, 'Pick…'),
    el('button', { type: 'button', 'data-action': 'send', onclick: send }, 'Send'));
}

function thresholds(ktcs, name, run, vehicle) {
  const current = vehicle?.energyLevelThresholdSet ?? {};
  const inputs = THRESHOLDS.map(([key, label]) => el('input', {
    type: 'number', min: 0, max: 100, step: 1, size: 3, name: key, title: `${label} (%)`, 'aria-label': `${label} (%)`,
    value: current[key] ?? '',
  }));
  const save = () => {
    const values = inputs.map((input) => (input.value.trim() === '' ? NaN : Number(input.value)));
    const problem = thresholdProblem(values);
    if (problem) return ktcs.notify(`Energy thresholds (${name}) not saved: ${problem}`, 'error');
    return run('Energy thresholds', 'PUT', '/energyLevelThresholdSet',
      Object.fromEntries(THRESHOLDS.map(([key], i) => [key, values[i]])));
  };
  return el('div', { className: 'action-row thresholds' }, el('span', { className: 'action-label' }, 'Energy %'),
    THRESHOLDS.map(([, label], i) => el('label', {}, label, inputs[i])),
    el('button', { type: 'button', 'data-action': 'save-thresholds', onclick: save }, 'Save'));
}

/**
 * What is wrong with [critical, good, sufficiently, fully] recharged thresholds, or null.
 * @param {number[]} thresholds
 */
export function thresholdProblem([critical, good, sufficiently, fully]) {
  const all = [critical, good, sufficiently, fully];
  if (all.some((value) => !Number.isInteger(value) || value < 0 || value > 100)) {
    return 'energy thresholds are whole percentages from 0 to 100';
  }
  if (critical > good) return `critical (${critical}) must not be above good (${good})`;
  if (sufficiently > fully) return `sufficiently recharged (${sufficiently}) must not be above fully recharged (${fully})`;
  return null;
}

function orderTypes(run, vehicle) {
  const text = (vehicle?.acceptableOrderTypes ?? []).map((t) => `${t.name}:${t.priority}`).join(', ');
  const input = el('input', { name: 'acceptable-order-types', value: text, size: 28, placeholder: 'Transport:0, Park:1 (* = any)', 'aria-label': 'Acceptable order types' });
  const save = () => run('Acceptable order types', 'PUT', '/acceptableOrderTypes',
    { acceptableOrderTypes: parseOrderTypes(input.value) });
  return el('div', { className: 'action-row' }, el('span', { className: 'action-label' }, 'Order types'), input,
    el('button', { type: 'button', 'data-action': 'save-order-types', onclick: save }, 'Save'));
}

/** "Transport:0, Park:1" as the web API's acceptable order types; a type without a priority gets 0. */
export function parseOrderTypes(text) {
  return text.split(',').map((part) => part.trim()).filter(Boolean).map((part) => {
    const [name, priority = '0'] = part.split(':').map((s) => s.trim());
    return { name, priority: Number(priority) };
  });
}

function driverChoice(ktcs, run, path) {
  const drivers = el('select', { 'aria-label': 'Driver', name: 'driver' }, el('option', { value: '' }, 'loading drivers…'));
  ktcs.api('GET', `${path}/commAdapter/attachmentInformation`).then((info) => {
    fill(drivers, (info?.availableCommAdapters ?? []).map((name) => el('option', {
      value: name, selected: name === info.attachedCommAdapter,
    }, name === info.attachedCommAdapter ? `${name} (attached)` : name)));
  }).catch((error) => fill(drivers, el('option', { value: '' }, `drivers unknown: ${error.message}`)));
  const attach = () => run(`Attach driver ${drivers.value}`, 'PUT', `/commAdapter/attachment?newValue=${enc(drivers.value)}`);
  return el('div', { className: 'action-row' }, el('span', { className: 'action-label' }, 'Driver'), drivers,
    el('button', { type: 'button', 'data-action': 'attach-driver', onclick: attach }, 'Attach'));
}
