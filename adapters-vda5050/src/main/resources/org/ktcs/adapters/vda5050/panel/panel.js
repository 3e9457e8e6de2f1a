// A VDA 5050 vehicle's panel in the overview's vehicle details: its MQTT connection state, the age of its last
// state message, its errors, its factsheet, and the instant actions an operator may send (pause, resume, state
// and factsheet requests, initialise the position on a point). Every action is a driver command the kernel checks.

const M = 'vda5050:';
const REFRESH_MS = 1000;

export default {
  mount(container, ktcs, vehicle, view) {
    const ui = build(ktcs, vehicle, container);
    ui.show(view);
    let stopped = false;
    const tick = async () => {
      if (stopped) return;
      try { ui.show(await vehicle.view()); } catch { /* tried again on the next tick */ }
      timer = setTimeout(tick, REFRESH_MS);
    };
    let timer = setTimeout(tick, REFRESH_MS);
    return () => {
      stopped = true;
      clearTimeout(timer);
      container.replaceChildren();
    };
  },
};

function build(ktcs, vehicle, container) {
  const send = (command, parameters, label) => vehicle.command(command, parameters, label);
  const points = (ktcs.model()?.points ?? []).map((p) => p.name).sort();
  const connection = h('strong', { 'data-role': 'connection' }, '—');
  const age = h('span', { 'data-role': 'state-age' }, '—');
  const order = h('span', { 'data-role': 'order' }, '—');
  const errors = h('span', { 'data-role': 'errors' }, 'none');
  const factsheet = h('pre', { 'data-role': 'factsheet', style: 'max-height:12em;overflow:auto;white-space:pre-wrap' }, 'not received');
  const point = h('select', { 'aria-label': 'Point', 'data-field': 'init-point' },
    h('option', { value: '' }, 'choose a point…'), ...points.map((name) => h('option', { value: name }, name)));
  const actions = h('div', { class: 'driver-actions' },
    button('Pause', 'start-pause', () => send(`${M}startPause`, {}, 'startPause')),
    button('Resume', 'stop-pause', () => send(`${M}stopPause`, {}, 'stopPause')),
    button('Request state', 'state-request', () => send(`${M}stateRequest`, {}, 'stateRequest')),
    button('Request factsheet', 'factsheet-request', () => send(`${M}factsheetRequest`, {}, 'factsheetRequest')),
    point,
    button('Init position', 'init-position', () => point.value && send(`${M}initPosition`, { point: point.value }, 'initPosition')));
  container.replaceChildren(
    row('Connection', connection), row('Last state', age), row('Order', order), row('Errors', errors),
    actions, h('details', {}, h('summary', {}, 'Factsheet'), factsheet));
  return {
    show(view) {
      const s = view?.state ?? {};
      connection.textContent = s.connection || '—';
      connection.dataset.state = s.connection || '';
      age.textContent = s.stateAgeMillis ? `${(Number(s.stateAgeMillis) / 1000).toFixed(1)} s ago` : 'none yet';
      order.textContent = s.orderId ? `${s.orderId} (update ${s.orderUpdateId || '—'})` : '—';
      errors.textContent = s.errors || 'none';
      if (s.factsheet) {
        try { factsheet.textContent = JSON.stringify(JSON.parse(s.factsheet), null, 1); } catch { factsheet.textContent = s.factsheet; }
      }
    },
  };
}

function row(label, value) {
  return h('div', { class: 'driver-row' }, h('span', {}, `${label}: `), value);
}

function button(text, role, onclick) {
  return h('button', { type: 'button', 'data-action': role, onclick }, text);
}

function h(tag, attributes, ...children) {
  const element = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) {
    if (key.startsWith('on')) element.addEventListener(key.slice(2), value);
    else element.setAttribute(key, value);
  }
  element.append(...children);
  return element;
}
