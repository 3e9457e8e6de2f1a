// A vehicle's acceptable order types in the modelling side bar. openTCS keeps them out of the plant model (they are
// the running vehicle's, set in the Operations Desk); kTCS does the same, so they are edited on the running vehicle
// (PUT /v1/vehicles/{name}/acceptableOrderTypes, kept across restarts by kTCS's state store), not in the draft.

import { el } from '../dom.js';
import { act, enc } from '../actions.js';
import { parseOrderTypes } from '../operator-actions.js';

/** What is wrong with "Transport:0, Park:1" as acceptable order types, or null. */
export function orderTypesProblem(text) {
  const types = parseOrderTypes(text);
  if (types.length === 0) return 'name at least one order type (* accepts every type)';
  const bad = types.find((t) => !t.name || !Number.isInteger(t.priority));
  return bad ? `"${bad.name || '(no name)'}:${bad.priority}" is not a type name with a whole-number priority` : null;
}

/**
 * The acceptable order types of vehicle [name]: editable when kTCS runs a vehicle of that name, else a note.
 * @param {import('./editor.js').ModellingMode} editor
 * @param {string} name
 */
export function orderTypesView(editor, name) {
  const vehicle = editor.client.objects('vehicles').find((v) => v.name === name);
  const title = el('h4', {}, 'Acceptable order types');
  if (!vehicle) {
    return el('section', { className: 'order-types' }, title,
      el('p', { className: 'hint' }, 'Set on the running vehicle once the model is published (a new vehicle accepts every type, *).'));
  }
  const text = (vehicle.acceptableOrderTypes ?? []).map((t) => `${t.name}:${t.priority}`).join(', ');
  const message = el('span', { className: 'field-error', role: 'alert' });
  const input = el('input', {
    type: 'text', name: 'acceptable-order-types', value: text, placeholder: 'Transport:0, Park:1 (* = any)',
    'aria-label': 'Acceptable order types',
    oninput: () => {
      const problem = orderTypesProblem(input.value);
      message.textContent = problem ?? '';
      input.classList.toggle('invalid', Boolean(problem));
    },
  });
  const save = () => {
    if (orderTypesProblem(input.value)) return;
    act(editor.ktcs, `Acceptable order types (${name})`, () => editor.ktcs.api('PUT', `/vehicles/${enc(name)}/acceptableOrderTypes`,
      { acceptableOrderTypes: parseOrderTypes(input.value) }));
  };
  return el('section', { className: 'order-types' }, title,
    el('p', { className: 'hint' }, 'Of the running vehicle, applied at once (not part of the model file, as in openTCS). Lower priority first.'),
    input, message, el('button', { type: 'button', 'data-action': 'save-order-types', onclick: save }, 'Save'));
}
