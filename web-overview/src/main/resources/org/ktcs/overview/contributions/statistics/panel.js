// Built-in panel: statistics, as in openTCS's Operations Desk. Finished orders per minute and order durations
// from the transport orders; how each vehicle spent its time (driving, operating, charging, idle), sampled each
// second while the page is open.

import { barChart, stackedBars } from './chart.js';

const MINUTES_SHOWN = 15;
const DURATIONS_SHOWN = 20;
const ACTIVITY_COLOURS = { driving: '#43a047', operating: '#1e88e5', charging: '#fdd835', idle: '#b0bec5' };

export default {
  mount(container, ktcs) {
    container.innerHTML = `
      <p data-role="totals"></p>
      <h3>Finished orders per minute (last ${MINUTES_SHOWN} minutes)</h3><div data-role="per-minute"></div>
      <h3>Durations of the last ${DURATIONS_SHOWN} finished orders (s)</h3><div data-role="durations"></div>
      <h3>Vehicle time since the page opened</h3><div data-role="activity"></div>`;
    const part = (role) => container.querySelector(`[data-role=${role}]`);
    const orders = new Map();
    const vehicles = new Map();
    const activity = new Map();
    const unsubscribeOrders = ktcs.subscribe('transportOrders', (message) => track(orders, message));
    const unsubscribeVehicles = ktcs.subscribe('vehicles', (message) => track(vehicles, message));
    // Timers in a hidden tab fire late or in bursts: each sample counts the time that really passed since the last.
    let lastSample = performance.now();
    const sample = setInterval(() => {
      const now = performance.now();
      const elapsedSeconds = (now - lastSample) / 1000;
      lastSample = now;
      for (const vehicle of vehicles.values()) {
        const kind = activityOf(vehicle, orders);
        const totals = activity.get(vehicle.name) ?? { driving: 0, operating: 0, charging: 0, idle: 0 };
        totals[kind] += elapsedSeconds;
        activity.set(vehicle.name, totals);
      }
    }, 1000);
    const render = () => {
      // Park and recharge orders (dispensable) are the kernel's own: one replaced by real work is no failure.
      const work = [...orders.values()].filter((o) => !o.dispensable);
      const own = orders.size - work.length;
      const finished = work.filter((o) => o.state === 'FINISHED');
      const failed = work.filter((o) => o.state === 'FAILED' || o.state === 'UNROUTABLE').length;
      const durations = finished.map((o) => (Date.parse(o.finishedTime) - Date.parse(o.creationTime)) / 1000)
        .filter((d) => Number.isFinite(d) && d >= 0);
      const average = durations.length ? durations.reduce((a, b) => a + b, 0) / durations.length : 0;
      part('totals').textContent = `Finished: ${finished.length} · failed: ${failed} · ` +
        `open: ${work.length - finished.length - failed} · mean duration: ${average.toFixed(1)} s · ` +
        `park/recharge orders (not counted): ${own}`;
      part('per-minute').replaceChildren(barChart(perMinute(finished)));
      const recent = finished.sort((a, b) => Date.parse(a.finishedTime) - Date.parse(b.finishedTime)).slice(-DURATIONS_SHOWN);
      part('durations').replaceChildren(barChart(recent.map((o, i) => ({
        label: String(i + 1), title: o.name, value: Math.round((Date.parse(o.finishedTime) - Date.parse(o.creationTime)) / 100) / 10,
      })), { colour: '#6a1b9a', unit: ' s' }));
      part('activity').replaceChildren(stackedBars([...activity.entries()].sort(([a], [b]) => a.localeCompare(b))
        .map(([label, parts]) => ({ label, parts })), ACTIVITY_COLOURS));
    };
    render();
    const repaint = setInterval(render, 2000);
    return () => {
      clearInterval(sample);
      clearInterval(repaint);
      unsubscribeOrders();
      unsubscribeVehicles();
    };
  },
};

function track(objects, message) {
  if (message.type === 'snapshot') {
    objects.clear();
    message.objects.forEach((object) => objects.set(object.name, object));
  } else if (message.type === 'event') {
    if (message.current) objects.set(message.current.name, message.current);
    else objects.delete(message.previous.name);
  }
}

function activityOf(vehicle, orders) {
  if (vehicle.state?.state === 'CHARGING') return 'charging';
  const order = vehicle.transportOrder && orders.get(vehicle.transportOrder);
  const driveOrder = order?.driveOrders?.[order.currentDriveOrderIndex];
  if (driveOrder?.state === 'OPERATING') return 'operating';
  if (driveOrder?.state === 'TRAVELLING' || vehicle.state?.state === 'EXECUTING') return 'driving';
  return 'idle';
}

function perMinute(finished) {
  const now = Date.now();
  const buckets = Array.from({ length: MINUTES_SHOWN }, (_, i) => ({ label: `-${MINUTES_SHOWN - 1 - i}`, value: 0 }));
  for (const order of finished) {
    const minutesAgo = Math.floor((now - Date.parse(order.finishedTime)) / 60000);
    if (minutesAgo >= 0 && minutesAgo < MINUTES_SHOWN) buckets[MINUTES_SHOWN - 1 - minutesAgo].value += 1;
  }
  return buckets;
}
