// The loopback (simulated) driver's controls in a vehicle's details. A simulated vehicle whose order was withdrawn
// between its load and its unload keeps the load and refuses every order that loads; the reset empties it.

import { el } from './dom.js';
import { act, enc } from './actions.js';

const LOOPBACK_DRIVER = 'loopback';
const SET_LOADED = 'tcs:virtualVehicle:setLoaded';

/**
 * The controls for vehicle name, hidden until its attachment information says the loopback driver drives it.
 * update(vehicle) shows its live load state.
 */
export function loopbackActions(ktcs, name) {
  const loadState = el('strong', { 'data-role': 'load-state' }, '—');
  const sendUnloaded = () => ktcs.api('POST', `/vehicles/${enc(name)}/commAdapter/message`,
    { type: SET_LOADED, parameters: [{ key: 'value', value: 'false' }] });
  const reset = el('button', {
    type: 'button',
    'data-action': 'reset-load',
    title: 'Tells the simulated vehicle it carries nothing, e.g. after its order was withdrawn between load and unload',
    onclick: () => act(ktcs, `Reset load (${name})`, sendUnloaded),
  }, 'Unload (reset load)');
  const element = el('div', { className: 'loopback-actions action-row', hidden: true, 'data-role': 'loopback' },
    el('span', { className: 'driver' }, 'Loopback driver'), el('span', {}, 'Load: ', loadState), reset);
  ktcs.api('GET', `/vehicles/${enc(name)}/commAdapter/attachmentInformation`)
    .then((attachment) => { element.hidden = attachment?.attachedCommAdapter !== LOOPBACK_DRIVER; })
    .catch((error) => ktcs.notify(`Driver of ${name} unknown: ${error.message}`, 'error'));
  return {
    element,
    update(vehicle) {
      const loaded = (vehicle.loadHandlingDevices ?? []).some((device) => device.full);
      loadState.textContent = loaded ? 'carries a load' : 'empty';
      loadState.className = loaded ? 'loaded' : '';
      reset.disabled = !loaded;
      reset.className = loaded ? 'primary' : '';
    },
  };
}
