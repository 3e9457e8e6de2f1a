// The browser plant overview: wires the client, the plant drawing, the operation views and the extensions' panels.

import { KtcsClient } from './client.js';
import { el, fill } from './dom.js';
import { PlantView } from './plant-view.js';
import { loadThemes } from './themes.js';
import { Tabs } from './tabs.js';
import { OrdersView } from './orders-view.js';
import { SequencesView } from './sequences-view.js';
import { VehiclesView } from './vehicles-view.js';
import { NotificationsView } from './notifications-view.js';
import { Details } from './details.js';
import { OrderDialog } from './order-dialog.js';
import { mountPanels } from './panels.js';
import { installLayerToggles, summaryOf } from './layers.js';
import { throttle } from './throttle.js';
import { installFleetControls } from './fleet-controls.js';
import { installModellingMode } from './modelling/mode-switch.js';

const toasts = document.getElementById('toasts');
const MAX_TOASTS = 5;

/** Shows a message to the operator; errors stay longer. */
function notify(text, level = 'info') {
  const toast = el('div', { className: `toast ${level}`, role: level === 'error' ? 'alert' : 'status' }, String(text));
  toasts.append(toast);
  // A burst of messages must not cover the page: the oldest go first.
  while (toasts.childElementCount > MAX_TOASTS) toasts.firstElementChild.remove();
  setTimeout(() => toast.remove(), level === 'error' ? 15000 : 6000);
}

window.addEventListener('error', (event) => notify(`Unexpected error: ${event.message}`, 'error'));
window.addEventListener('unhandledrejection', (event) => notify(`Unexpected error: ${event.reason?.message ?? event.reason}`, 'error'));

async function fetchJson(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
  return response.json();
}

async function accessKey(required) {
  if (!required) return '';
  const button = document.getElementById('access-key-button');
  button.hidden = false;
  button.onclick = () => { sessionStorage.removeItem('ktcs.accessKey'); location.reload(); };
  for (;;) {
    const key = sessionStorage.getItem('ktcs.accessKey') ?? await askForKey();
    const probe = await fetch('/v1/kernel/version', { headers: { 'X-Api-Access-Key': key } });
    if (probe.ok) {
      sessionStorage.setItem('ktcs.accessKey', key);
      return key;
    }
    sessionStorage.removeItem('ktcs.accessKey');
    notify('The access key was refused by kTCS.', 'error');
  }
}

function askForKey() {
  const dialog = /** @type {HTMLDialogElement} */ (document.getElementById('key-dialog'));
  const input = /** @type {HTMLInputElement} */ (document.getElementById('key-input'));
  return new Promise((resolve) => {
    dialog.onclose = () => resolve(input.value);
    dialog.showModal();
  });
}

function installConnectionIndicator(client) {
  const indicator = document.getElementById('connection');
  let everConnected = false;
  client.onConnectionChange((connected) => {
    indicator.className = `connection ${connected ? 'online' : 'offline'}`;
    indicator.textContent = connected ? 'live' : (everConnected ? 'reconnecting…' : 'connecting…');
    if (!connected && everConnected) indicator.title = 'Connection lost; reconnecting by itself';
    everConnected ||= connected;
  });
}

async function start() {
  const [settings, extensions] = await Promise.all([
    fetchJson('/overview/settings.json'), fetchJson('/overview/extensions.json'),
  ]);
  const client = new KtcsClient({ accessKey: await accessKey(settings.accessKeyRequired) });
  const themes = await loadThemes(extensions, settings, notify);
  const ktcs = {
    api: (method, path, body) => client.api(method, path, body),
    subscribe: (topic, listener) => client.subscribe(topic, listener),
    model: () => client.objects('plantModel')[0] ?? null,
    notify,
  };
  const details = new Details(document.getElementById('details'), { ktcs, client });
  const plant = new PlantView(document.getElementById('plant-canvas'), {
    themes,
    onSelect: (selection) => details.show(selection),
  });
  details.plant = plant;
  const refreshDetails = throttle(() => details.refresh(), 250);
  const tabs = new Tabs(document.getElementById('tabs'), document.getElementById('tab-bodies'));
  const dialog = new OrderDialog(document.getElementById('order-dialog'), { ktcs, client });
  new VehiclesView(tabs.add('vehicles', 'Vehicles'), { client, details });
  new OrdersView(tabs.add('orders', 'Orders'), { client, details, dialog });
  new SequencesView(tabs.add('sequences', 'Sequences'), { client, details });
  new NotificationsView(tabs.add('notifications', 'Notifications'), { client, tabs });
  await mountPanels(extensions, tabs, ktcs, notify);
  tabs.activate('vehicles');
  installPlantControls(plant);
  installFleetControls(document.getElementById('fleet-controls'), { ktcs, client, plant });
  installConnectionIndicator(client);
  const modelling = installModellingMode({ plant, ktcs, client, details });

  let refitAfterReplacement = false;
  client.onModelReplaced((name) => {
    notify(`Plant model replaced: ${name}`, 'info');
    details.show(null);
    dialog.close();
    refitAfterReplacement = true;
  });
  client.subscribe('plantModel', (message) => {
    if (message.type === 'snapshot') {
      const model = message.objects[0];
      modelling.runningModel = model;
      if (!modelling.active) plant.setModel(model);
      if (refitAfterReplacement) {
        refitAfterReplacement = false;
        plant.userMoved = false;
        plant.fit();
      }
      refreshDetails();
      document.getElementById('model-name').textContent = model.name;
      document.getElementById('plant-summary').textContent = summaryOf(model);
      installLayerToggles(document.getElementById('layers'), model, plant);
    } else if (message.type === 'event') {
      if (!modelling.active) plant.updateElement(message.current);
      refreshDetails();
    }
  });
  client.subscribe('vehicles', () => {
    plant.vehicles.setVehicles(client.objects('vehicles'));
    refreshDetails();
  });
  client.subscribe('orderSequences', () => refreshDetails());
  client.subscribe('transportOrders', () => {
    plant.vehicles.setOrders(client.state.get('transportOrders') ?? new Map());
    refreshDetails();
  });
  client.connect();
  exposeForDiagnostics(plant, client, themes, modelling);
}

function installPlantControls(plant) {
  document.getElementById('fit').onclick = () => { plant.userMoved = false; plant.fit(); };
  document.getElementById('zoom-in').onclick = () => { plant.userMoved = true; plant.zoom(1.4); };
  document.getElementById('zoom-out').onclick = () => { plant.userMoved = true; plant.zoom(1 / 1.4); };
  document.getElementById('show-labels').onchange = (event) =>
    plant.setLabels(/** @type {HTMLInputElement} */ (event.target).checked);
}

// What the browser tests and the drawing benchmark read; also handy in the browser's console.
function exposeForDiagnostics(plant, client, themes, modelling) {
  /** @type {any} */ (window).ktcsOverview = {
    /** The modelling mode (its draft, selection, problems and the marks drawn on elements). */
    modelling,
    drawn: () => ({ ...plant.lastDrawn, vehicles: plant.vehicles.drawn.size }),
    /** The resources drawn as held (allocated or claimed), the paths drawn as routes ahead and as highlighted route. */
    drawnResources: () => [...plant.vehicles.drawnResources].sort(),
    drawnRoutes: () => [...plant.vehicles.drawnRoutes].sort(),
    highlightedRoute: () => [...plant.highlightedRoute],
    pagePositionOf: (kind, name) => plant.pagePositionOf(kind, name),
    /** The vehicle the view follows (null if none) and the boxes of the vehicle labels drawn last. */
    following: () => plant.following ?? null,
    vehicleLabels: () => plant.vehicles.labelBoxes.map((box) => ({ ...box })),
    /** The boxes of the location and point names drawn last. */
    plantLabels: () => plant.plantLabels.map((box) => ({ ...box })),
    connected: () => client.connected,
    /** The style the configured vehicle theme gives a vehicle now. */
    vehicleStyle: (name) => {
      const vehicle = client.state.get('vehicles')?.get(name);
      return vehicle ? themes.vehicleStyle(vehicle) : null;
    },
    /** Closes the WebSocket as a network failure would; the client reconnects by itself after offlineMs at least. */
    dropConnection: (offlineMs = 0) => client.dropConnection(offlineMs),
    /** Draws frames of the static plant at changing zoom levels and answers the draw times in ms. */
    benchmark(frames = 30, warmUp = 5) {
      const times = [];
      for (let i = 0; i < frames + warmUp; i += 1) {
        plant.view.zoomAt(i % 2 === 0 ? 1.15 : 1 / 1.15, plant.width / 2, plant.height / 2);
        plant.drawStatic();
        times.push(plant.lastDrawn.staticMs);
        const started = performance.now();
        plant.drawOverlay(performance.now());
        times[times.length - 1] += performance.now() - started;
      }
      plant.fit();
      return times.slice(warmUp);
    },
  };
}

start().catch((error) => {
  fill(document.getElementById('model-name'), 'not loaded');
  notify(`The overview could not start: ${error.message}`, 'error');
});
