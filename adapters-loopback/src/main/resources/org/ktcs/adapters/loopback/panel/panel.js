// The loopback (simulated) vehicle's panel in the overview's vehicle details, as openTCS's loopback panel: position
// (choose a point, or drag the vehicle onto one in the plant view), orientation, energy, state, load, pause,
// single-step mode with its step button, time factor, the command queue and the latest driver events.
// Every change is a driver command the kernel checks before the vehicle's driver carries it out.

const M = 'tcs:virtualVehicle:';
const MAX_EVENTS = 8;
const REFRESH_MS = 400;

export default {
  mount(container, ktcs, vehicle, view) {
    const ui = build(ktcs, vehicle, container);
    let current = view;
    let timer = null;
    const refresh = () => {
      if (timer) return;
      timer = setTimeout(async () => {
        timer = null;
        try {
          current = await vehicle.view();
          ui.showDriver(current);
        } catch { /* the next vehicle event tries again */ }
      }, REFRESH_MS);
    };
    ui.showDriver(current);
    ui.onCommandDone = refresh;
    const stopVehicles = ktcs.subscribe('vehicles', (message) => {
      const object = message.type === 'snapshot' ? message.objects.find((v) => v.name === vehicle.name) : message.current;
      if (object?.name !== vehicle.name) return;
      ui.showVehicle(object);
      refresh();
    });
    const events = [];
    const stopEvents = ktcs.subscribe('driverEvents', (message) => {
      const incoming = message.type === 'snapshot' ? message.objects : [message.current];
      if (message.type === 'snapshot') events.length = 0;
      events.push(...incoming.filter((event) => event?.vehicle === vehicle.name));
      events.splice(0, Math.max(0, events.length - MAX_EVENTS));
      ui.showEvents(events);
      refresh();
    });
    const stopDrop = vehicle.allowDrop((point) => ui.place(point));
    return () => {
      clearTimeout(timer);
      stopVehicles();
      stopEvents();
      stopDrop();
      container.replaceChildren();
    };
  },
};

function build(ktcs, vehicle, container) {
  const send = async (command, parameters, label) => {
    const result = await vehicle.command(command, parameters, label);
    ui.onCommandDone?.();
    return result;
  };
  const states = vehicle.commands.find((c) => c.name === `${M}setState`)?.parameters[0]?.values ?? [];
  const points = (ktcs.model()?.points ?? []).map((p) => p.name).sort(naturally);

  const point = h('select', { 'aria-label': 'Point', 'data-field': 'position' },
    h('option', { value: '' }, 'choose a point…'), ...points.map((name) => h('option', { value: name }, name)));
  const angle = h('input', { type: 'number', min: -360, max: 360, step: 'any', size: 5, placeholder: '—', title: 'unknown until set', 'aria-label': 'Orientation (degrees)', 'data-field': 'orientation' });
  const energy = h('input', { type: 'number', min: 0, max: 100, step: 1, size: 4, 'aria-label': 'Energy (%)', 'data-field': 'energy' });
  const state = h('select', { 'aria-label': 'Vehicle state', 'data-field': 'state' }, ...states.map((s) => h('option', { value: s }, s)));
  const timeFactor = h('input', { type: 'number', min: 0.01, max: 1000, step: 'any', size: 5, 'aria-label': 'Time factor', 'data-field': 'time-factor' });
  const loadState = h('strong', { 'data-role': 'load-state' }, '—');
  const reset = button('Unload (reset load)', 'reset-load', () => send(`${M}setLoaded`, { value: 'false' }, 'Reset load'),
    'Tells the simulated vehicle it carries nothing, e.g. after its order was withdrawn between load and unload');
  const load = button('Load', 'set-loaded', () => send(`${M}setLoaded`, { value: 'true' }, 'Set loaded'));
  const pause = button('Pause', 'pause', () => {
    const paused = pause.dataset.paused !== 'true';
    return ktcs.api('PUT', `/vehicles/${encodeURIComponent(vehicle.name)}/paused?newValue=${paused}`)
      .then(() => ui.onCommandDone?.(), (error) => ktcs.notify(`Pause (${vehicle.name}) failed: ${error.message}`, 'error'));
  });
  const singleStep = h('input', { type: 'checkbox', 'data-field': 'single-step',
    onchange: () => send(`${M}setSingleStepModeEnabled`, { value: String(singleStep.checked) }, 'Single-step mode') });
  const step = button('Step', 'step', () => send(`${M}triggerSingleStep`, {}, 'Step'), 'Carries out the next command');
  const queue = h('tbody', {});
  const events = h('ul', { className: 'driver-events', 'data-role': 'driver-events' });

  const ui = {
    place: (name) => send(`${M}setPosition`, { position: name }, `Place on ${name}`),
    showVehicle(object) {
      if (document.activeElement !== energy) energy.value = object.energyLevel;
      if (document.activeElement !== state) state.value = object.state?.state ?? object.state;
      const orientation = object.pose?.orientationAngle;
      if (document.activeElement !== angle && typeof orientation === 'number') angle.value = orientation;
      const loaded = (object.loadHandlingDevices ?? []).some((device) => device.full);
      loadState.textContent = loaded ? 'carries a load' : 'empty';
      loadState.className = loaded ? 'loaded' : '';
      reset.disabled = !loaded;
      reset.className = loaded ? 'primary' : '';
      load.disabled = loaded;
      pause.dataset.paused = String(Boolean(object.paused));
      pause.textContent = object.paused ? 'Resume' : 'Pause';
    },
    showDriver(view) {
      const driverState = view?.state ?? {};
      singleStep.checked = driverState.singleStepMode === 'true';
      step.disabled = driverState.waitingForStep !== 'true';
      step.className = step.disabled ? '' : 'primary';
      if (document.activeElement !== timeFactor && driverState.timeFactor) timeFactor.value = Number(driverState.timeFactor);
      const rows = queueRows(view?.commandQueue ?? [], driverState.waitingForStep === 'true');
      queue.replaceChildren(...rows.map((cells) => h('tr', {}, ...cells.map((c) => h('td', {}, c)))));
      if (queue.children.length === 0) queue.append(h('tr', {}, h('td', { colSpan: 3 }, 'no commands')));
    },
    showEvents(list) {
      events.replaceChildren(...list.slice().reverse().map((event) => h('li', {}, eventText(event))));
      if (list.length === 0) events.append(h('li', { className: 'muted' }, 'none yet'));
    },
  };

  container.append(h('div', { className: 'loopback-panel', 'data-role': 'loopback' },
    row('Position', point, button('Set', 'set-position', () => point.value && ui.place(point.value)),
      h('span', { className: 'muted' }, 'or drag the vehicle onto a point')),
    row('Orientation', angle, '°', button('Set', 'set-orientation',
      () => send(`${M}setOrientationAngle`, { angle: angle.value }, `Orientation ${angle.value}°`))),
    row('Energy', energy, '%', button('Set', 'set-energy', () => send(`${M}setEnergyLevel`, { value: energy.value }, `Energy ${energy.value}%`))),
    row('State', state, button('Set', 'set-state', () => send(`${M}setState`, { value: state.value }, `State ${state.value}`))),
    row('Load', loadState, reset, load),
    row('Simulation', pause, h('label', {}, singleStep, ' single step'), step),
    row('Time factor', timeFactor, '×', button('Set', 'set-time-factor',
      () => send(`${M}setTimeFactor`, { value: timeFactor.value }, `Time factor ${timeFactor.value}`))),
    h('h4', {}, 'Command queue'),
    h('table', { className: 'command-queue', 'data-role': 'command-queue' },
      h('thead', {}, h('tr', {}, h('th', {}, 'Stage'), h('th', {}, 'Step'), h('th', {}, 'Operation'))), queue),
    h('h4', {}, 'Driver events'),
    events));
  ui.showEvents([]);
  return ui;
}

/**
 * The command queue's table rows: [stage, step, operation]. The first sent command is the one under way, or in
 * single-step mode the one the next step carries out.
 */
export function queueRows(commands, waitingForStep = false) {
  const label = { SENT: 'sent', WAITING_FOR_RESOURCES: 'waiting for resources', QUEUED: 'queued' };
  const first = waitingForStep ? 'next step' : 'current';
  return commands.map((command, index) => [
    index === 0 && command.stage === 'SENT' ? first : (label[command.stage] ?? command.stage),
    command.path ?? command.destinationPoint,
    command.operation === 'NOP' ? '—' : `${command.operation}${command.location ? ` @ ${command.location}` : ''}`,
  ]);
}

/** One driver event as a line: time, type without the driver's prefix, payload. */
export function eventText(event) {
  const time = new Date(event.timestamp).toLocaleTimeString();
  const type = event.type.replace(/^loopback:|^tcs:virtualVehicle:/, '');
  const payload = Object.entries(event.payload ?? {}).map(([k, v]) => `${k}=${v}`).join(' ');
  return `${time} ${type}${payload ? ` · ${payload}` : ''}`;
}

function naturally(a, b) {
  return a.localeCompare(b, undefined, { numeric: true });
}

function row(label, ...controls) {
  return h('div', { className: 'action-row' }, h('span', { className: 'row-label' }, label), ...controls);
}

function button(text, action, onclick, title) {
  return h('button', { type: 'button', 'data-action': action, onclick, title }, text);
}

function h(tag, attrs = {}, ...children) {
  const element = document.createElement(tag);
  for (const [key, value] of Object.entries(attrs)) {
    if (value === undefined || value === null) continue;
    if (key.startsWith('data-') || key.startsWith('aria-')) element.setAttribute(key, value);
    else element[key] = value;
  }
  element.append(...children.filter((c) => c !== null && c !== undefined).map((c) => (c instanceof Node ? c : String(c))));
  return element;
}
