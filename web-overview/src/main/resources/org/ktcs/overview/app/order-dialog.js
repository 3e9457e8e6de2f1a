// The create-order dialog: destinations from the model (locations with the operations their type and link allow,
// or points with MOVE/PARK), intended vehicle, deadline, type and an optional name.

import { el, fill } from './dom.js';
import { enc } from './actions.js';

const POINT_OPERATIONS = ['MOVE', 'PARK'];

export class OrderDialog {
  constructor(dialog, { ktcs, client }) {
    this.dialog = dialog;
    this.ktcs = ktcs;
    this.client = client;
  }

  /** Closes the dialog if it is open (its choices come from a model that may be gone). */
  close() {
    if (this.dialog.open) this.dialog.close();
  }

  open() {
    const model = this.ktcs.model();
    if (!model) {
      this.ktcs.notify('The plant model is not loaded yet.', 'error');
      return;
    }
    this.rows = el('div', { className: 'destinations' });
    this.addDestination(model);
    this.name = el('input', { name: 'name', placeholder: 'generated when empty', size: 24 });
    this.vehicle = el('select', { name: 'intendedVehicle' }, el('option', { value: '' }, 'any vehicle'),
      this.client.objects('vehicles').map((v) => v.name).sort().map((name) => el('option', { value: name }, name)));
    this.deadline = el('input', { name: 'deadline', type: 'datetime-local' });
    this.type = el('input', { name: 'type', value: '-', size: 12 });
    this.error = el('p', { className: 'form-error', role: 'alert' });
    fill(this.dialog, el('form', { method: 'dialog', onsubmit: (event) => this.submit(event) },
      el('h2', {}, 'New transport order'),
      this.rows,
      el('button', { type: 'button', onclick: () => this.addDestination(model) }, '+ Destination'),
      el('div', { className: 'form-grid' },
        el('label', {}, 'Name', this.name), el('label', {}, 'Intended vehicle', this.vehicle),
        el('label', {}, 'Deadline', this.deadline), el('label', {}, 'Type', this.type)),
      this.error,
      el('menu', {},
        el('button', { type: 'button', onclick: () => this.dialog.close() }, 'Cancel'),
        this.submitButton = el('button', { type: 'submit', className: 'primary', 'data-action': 'create-order' }, 'Create'))));
    this.dialog.showModal();
  }

  addDestination(model) {
    const operations = el('select', { name: 'operation', 'aria-label': 'Operation' });
    const target = el('select', { name: 'destination', 'aria-label': 'Destination', onchange: () => fillOperations() },
      targetOptions(model));
    const fillOperations = () => fill(operations, operationsFor(model, target.value).map((op) => el('option', { value: op }, op)));
    fillOperations();
    const properties = el('div', { className: 'destination-properties' });
    const row = el('div', { className: 'destination-row' }, target, operations,
      el('button', { type: 'button', 'data-action': 'add-property', title: 'Add a property for the vehicle at this destination', onclick: () => properties.append(propertyPair()) }, '+ Property'),
      el('button', { type: 'button', title: 'Remove', onclick: () => row.remove() }, '×'),
      properties);
    this.rows.append(row);
  }

  async submit(event) {
    event.preventDefault();
    const rows = [...this.rows.querySelectorAll('.destination-row')];
    const problem = rows.map((row, i) => propertiesProblem(pairsOf(row), i + 1)).find(Boolean);
    if (problem) {
      this.error.textContent = problem;
      return;
    }
    const destinations = rows.map((row) => ({
      locationName: row.querySelector('[name=destination]').value.replace(/^(location|point):/, ''),
      operation: row.querySelector('[name=operation]').value,
      properties: pairsOf(row).filter((p) => p.key !== '' || p.value !== ''),
    }));
    if (destinations.length === 0) {
      this.error.textContent = 'Add at least one destination.';
      return;
    }
    if (destinations.some((d) => !d.operation)) {
      this.error.textContent = 'Every destination needs an operation its location type allows.';
      return;
    }
    const name = this.name.value.trim();
    const body = {
      incompleteName: name === '',
      destinations,
      type: this.type.value.trim() || '-',
      intendedVehicle: this.vehicle.value || null,
      deadline: this.deadline.value ? new Date(this.deadline.value).toISOString() : null,
    };
    if (this.submitButton.disabled) return;
    this.submitButton.disabled = true;
    try {
      const created = await this.ktcs.api('POST', `/transportOrders/${enc(name || 'Order-')}`, body);
      this.ktcs.notify(`Created transport order ${created?.name ?? name}`, 'info');
      this.dialog.close();
    } catch (error) {
      this.error.textContent = error.message;
      this.ktcs.notify(`Creating the order failed: ${error.message}`, 'error');
    } finally {
      this.submitButton.disabled = false;
    }
  }
}

function propertyPair() {
  const pair = el('span', { className: 'property-pair' },
    el('input', { name: 'property-key', placeholder: 'key', size: 12, 'aria-label': 'Property key' }),
    el('input', { name: 'property-value', placeholder: 'value', size: 12, 'aria-label': 'Property value' }),
    el('button', { type: 'button', title: 'Remove property', onclick: () => pair.remove() }, '×'));
  return pair;
}

function pairsOf(row) {
  return [...row.querySelectorAll('.property-pair')].map((pair) => ({
    key: pair.querySelector('[name=property-key]').value.trim(),
    value: pair.querySelector('[name=property-value]').value,
  }));
}

/** What is wrong with destination [number]'s properties (a value without key, a key given twice), or null. */
export function propertiesProblem(pairs, number) {
  const seen = new Set();
  for (const { key, value } of pairs) {
    if (key === '' && value === '') continue;
    if (key === '') return `Destination ${number}: the property with value '${value}' needs a key.`;
    if (seen.has(key)) return `Destination ${number}: property '${key}' is given twice.`;
    seen.add(key);
  }
  return null;
}

/** The model's locations and points as option groups, valued `location:NAME` / `point:NAME`. */
export function targetOptions(model) {
  return [
    el('optgroup', { label: 'Locations' },
      [...model.locations].sort(byName).map((l) => el('option', { value: `location:${l.name}` }, l.name))),
    el('optgroup', { label: 'Points' },
      [...model.points].sort(byName).map((p) => el('option', { value: `point:${p.name}` }, p.name))),
  ];
}

/** The operations a target (`location:NAME` or `point:NAME`) offers. */
export function operationsFor(model, value) {
  if (value.startsWith('point:')) return POINT_OPERATIONS;
  const location = model.locations.find((l) => `location:${l.name}` === value);
  const type = model.locationTypes.find((t) => t.name === location?.typeName);
  const allowed = new Set(type?.allowedOperations ?? []);
  // Operations a link of the location allows are offered as well as its type's.
  for (const link of location?.links ?? []) link.allowedOperations.forEach((op) => allowed.add(op));
  return [...allowed].sort();
}

function byName(a, b) {
  return a.name.localeCompare(b.name);
}
