// Built-in panel: a continuous load generator, as in openTCS's Operations Desk. It creates transport orders between
// the chosen locations at a fixed rate until stopped, through the web API like any other client.

const MAX_RATE_PER_MINUTE = 600;
// More requests than this still waiting means the kernel is not keeping up: a tick is skipped rather than piling up.
const MAX_IN_FLIGHT = 4;

export default {
  mount(container, ktcs) {
    let timer = null;
    let created = 0;
    let failed = 0;
    const ui = build(container);
    const status = (text) => { ui.status.textContent = text; };
    const report = () => status(`${timer ? 'Running' : 'Stopped'} · created ${created} · failed ${failed}`);

    const unsubscribe = ktcs.subscribe('plantModel', (message) => {
      if (message.type === 'snapshot') fillLocations(ui, message.objects[0]);
    });

    let inFlight = 0;
    let lastSucceeded = true;

    const fail = (problem) => {
      ui.error.textContent = problem;
      ktcs.notify(`Load generator: ${problem}`, 'error');
    };

    const createOne = async () => {
      if (inFlight >= MAX_IN_FLIGHT) return;
      const from = pick(selected(ui.from));
      const to = from && pick(selected(ui.to).filter((option) => option.value !== from.value));
      if (!from || !to) {
        stop();
        fail(from ? 'no destination other than the chosen source is selected' : 'no source is selected');
        return;
      }
      inFlight += 1;
      try {
        await ktcs.api('POST', '/transportOrders/Load-', {
          incompleteName: true,
          destinations: [
            { locationName: from.value, operation: from.dataset.operation },
            { locationName: to.value, operation: to.dataset.operation },
          ],
        });
        created += 1;
        lastSucceeded = true;
      } catch (error) {
        failed += 1;
        // One notification per run of failures, not one per tick.
        if (lastSucceeded) fail(`creating an order failed: ${error.message}`);
        else ui.error.textContent = error.message;
        lastSucceeded = false;
      } finally {
        inFlight -= 1;
      }
      report();
    };

    const stop = () => {
      clearInterval(timer);
      timer = null;
      ui.toggle.textContent = 'Start';
      report();
    };

    ui.toggle.onclick = () => {
      if (timer) {
        stop();
        return;
      }
      const problem = checkInput(ui);
      if (problem) {
        ui.error.textContent = problem;
        ktcs.notify(`Load generator: ${problem}`, 'error');
        return;
      }
      ui.error.textContent = '';
      lastSucceeded = true;
      timer = setInterval(createOne, 60000 / Number(ui.rate.value));
      ui.toggle.textContent = 'Stop';
      createOne();
      report();
    };
    report();
    return () => {
      stop();
      unsubscribe();
    };
  },
};

function build(container) {
  container.innerHTML = `
    <p>Creates orders from a random source to a random destination, at a fixed rate.</p>
    <div style="display:grid;grid-template-columns:1fr 1fr;gap:8px">
      <label>Sources (load)<select data-role="from" multiple size="8" style="width:100%"></select></label>
      <label>Destinations (unload)<select data-role="to" multiple size="8" style="width:100%"></select></label>
    </div>
    <p><label>Orders per minute <input data-role="rate" type="number" min="1" max="${MAX_RATE_PER_MINUTE}" value="6"
      style="width:6em"></label>
      <button type="button" data-role="toggle" class="primary">Start</button></p>
    <p data-role="status"></p>
    <p data-role="error" class="form-error"></p>`;
  const part = (role) => container.querySelector(`[data-role=${role}]`);
  return {
    from: part('from'), to: part('to'), rate: part('rate'), toggle: part('toggle'), status: part('status'), error: part('error'),
  };
}

function fillLocations(ui, model) {
  const types = new Map(model.locationTypes.map((type) => [type.name, type]));
  const options = (preferred, avoided) => model.locations
    .map((location) => ({ location, operation: chooseOperation(types.get(location.typeName), preferred, avoided) }))
    .filter(({ operation }) => operation)
    .sort((a, b) => a.location.name.localeCompare(b.location.name))
    .map(({ location, operation }) => {
      const option = document.createElement('option');
      option.value = location.name;
      option.dataset.operation = operation;
      option.textContent = `${location.name} (${operation})`;
      return option;
    });
  refill(ui.from, options(/load/i, /unload/i));
  refill(ui.to, options(/unload|drop/i, null));
}

// A new snapshot (reconnect, missed events, replaced model) must not lose what the operator chose.
function refill(select, options) {
  const kept = new Set(selected(select).map((option) => option.value));
  options.forEach((option) => { option.selected = kept.has(option.value); });
  select.replaceChildren(...options);
}

// The operation a generated order asks for at a location: one that sounds right, else the first the type allows.
function chooseOperation(type, preferred, avoided) {
  const operations = (type?.allowedOperations ?? []).filter((op) => !/charge/i.test(op));
  return operations.find((op) => preferred.test(op) && !(avoided && avoided.test(op))) ?? operations[0];
}

function checkInput(ui) {
  const rate = Number(ui.rate.value);
  if (!(rate >= 1 && rate <= MAX_RATE_PER_MINUTE)) return `the rate must be between 1 and ${MAX_RATE_PER_MINUTE} orders per minute`;
  if (selected(ui.from).length === 0) return 'choose at least one source';
  if (selected(ui.to).length === 0) return 'choose at least one destination';
  if (selected(ui.from).length === 1 && selected(ui.to).length === 1 && selected(ui.from)[0].value === selected(ui.to)[0].value) {
    return 'choose a destination other than the source';
  }
  return null;
}

function selected(select) {
  return [...select.selectedOptions];
}

function pick(list) {
  return list.length === 0 ? undefined : list[Math.floor(Math.random() * list.length)];
}
