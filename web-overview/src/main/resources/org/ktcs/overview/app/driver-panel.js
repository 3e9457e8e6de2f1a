// A vehicle's driver panel in its details: the panel the vehicle's driver contributes (an ES module served at
// /overview/drivers/{driver}/), mounted with a handle for this one vehicle. Vehicles whose driver has no panel show
// nothing here.

import { el } from './dom.js';
import { act, enc } from './actions.js';

// Whether the operator keeps driver panels open; folding one folds them for the next vehicle too.
let open = true;

/** The section for vehicle name; close() unmounts the panel when the details show something else. */
export function driverPanel(ktcs, plant, name) {
  const element = el('details', { className: 'driver-panel', hidden: true, open, 'data-role': 'driver-panel' });
  element.addEventListener('toggle', () => { open = element.open; });
  const path = `/vehicles/${enc(name)}`;
  let closed = false;
  let unmount = null;
  const mount = async (view) => {
    if (closed || !view?.panel) return;
    const module = await import(`/overview/drivers/${enc(view.driver)}/${view.panel.module}`);
    if (closed) return;
    const body = el('div', { className: 'driver-panel-body' });
    element.append(el('summary', {}, view.panel.title), body);
    element.hidden = false;
    unmount = module.default.mount(body, ktcs, vehicleHandle(ktcs, plant, name, path, view), view) ?? null;
  };
  ktcs.api('GET', `${path}/driverPanel`).then(mount).catch((error) => {
    // 409: the vehicle has no driver attached, so there is no panel to show.
    if (!closed && error.status !== 409) ktcs.notify(`Driver panel of ${name}: ${error.message}`, 'error');
  });
  return {
    element,
    close() {
      closed = true;
      unmount?.();
      if (plant?.vehicleDrop?.vehicle === name) plant.vehicleDrop = null;
    },
  };
}

// What a driver panel may do for its vehicle (web-overview/README.md, "Driver panels").
function vehicleHandle(ktcs, plant, name, path, view) {
  return {
    name,
    driver: view.driver,
    commands: view.panel.commands,
    view: () => ktcs.api('GET', `${path}/driverPanel`),
    command: (command, parameters = {}, label = command) => act(ktcs, `${label} (${name})`,
      () => ktcs.api('POST', `${path}/driverCommand`, { driver: view.driver, command, parameters })),
    allowDrop(drop) {
      if (!plant) return () => {};
      plant.vehicleDrop = { vehicle: name, drop };
      return () => { if (plant.vehicleDrop?.vehicle === name) plant.vehicleDrop = null; };
    },
  };
}
