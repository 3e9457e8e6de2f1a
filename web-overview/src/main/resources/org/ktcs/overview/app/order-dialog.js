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
      el('optgroup', { label: 'Locations' },
        [...model.locations].sort(byName).map((l) => el('option', { value: `location:${l.name}` }, l.name))),
      el('optgroup', { label: 'Points' },
        [...model.points].sort(byName).map((p) => el('option', { value: `point:${p.name}` }, p.name))));
    const fillOperations = () => fill(operations, operationsFor(model, target.value).map((op) => el('option', { value: op }, op)));
    fillOperations();
    const row = el('div', { className: 'destination-row' }, target, operations,
      el('button', { type: 'button', title: 'Remove', onclick: () => row.remove() }, '×'));
    this.rows.append(row);
  }

  async submit(event) {
    event.preventDefault();
    const destinations = [...this.rows.querySelectorAll('.destination-row')].map((row) => ({
      locationName: row.querySelector('[name=destination]').value.replace(/^(location|point):/, ''),
      operation: row.querySelector('[name=operation]').value,
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

function operationsFor(model, value) {
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
