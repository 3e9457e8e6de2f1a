// Built-in panel: which vehicle holds (allocated) and has claimed which resources, live.

export default {
  mount(container, ktcs) {
    container.innerHTML = `
      <p>Allocated resources are held by the vehicle now; claimed ones are reserved for the rest of its route.</p>
      <table class="grid" data-role="vehicles"><thead><tr><th>Vehicle</th><th>Allocated</th><th>Claimed</th></tr></thead>
      <tbody></tbody></table>
      <h3>By resource</h3>
      <table class="grid" data-role="resources"><thead><tr><th>Resource</th><th>Allocated to</th><th>Claimed by</th></tr>
      </thead><tbody></tbody></table>`;
    const vehicles = new Map();
    const render = () => {
      const sorted = [...vehicles.values()].sort((a, b) => a.name.localeCompare(b.name));
      rows(container.querySelector('[data-role=vehicles] tbody'), sorted.map((vehicle) => [
        vehicle.name, names(vehicle.allocatedResources), names(vehicle.claimedResources),
      ]));
      const byResource = new Map();
      const note = (resource, column, vehicle) => {
        if (!byResource.has(resource)) byResource.set(resource, [new Set(), new Set()]);
        byResource.get(resource)[column].add(vehicle);
      };
      for (const vehicle of sorted) {
        (vehicle.allocatedResources ?? []).flat().forEach((resource) => note(resource, 0, vehicle.name));
        (vehicle.claimedResources ?? []).flat().forEach((resource) => note(resource, 1, vehicle.name));
      }
      rows(container.querySelector('[data-role=resources] tbody'), [...byResource.entries()]
        .sort(([a], [b]) => a.localeCompare(b))
        .map(([resource, [allocated, claimed]]) => [resource, listed(allocated), listed(claimed)]));
    };
    let scheduled = false;
    return ktcs.subscribe('vehicles', (message) => {
      if (message.type === 'snapshot') {
        vehicles.clear();
        message.objects.forEach((vehicle) => vehicles.set(vehicle.name, vehicle));
      } else if (message.type === 'event') {
        if (message.current) vehicles.set(message.current.name, message.current);
        else vehicles.delete(message.previous.name);
      }
      if (!scheduled) {
        scheduled = true;
        setTimeout(() => { scheduled = false; render(); }, 200);
      }
    });
  },
};

// A vehicle's resource sets repeat a point in consecutive sets (the point it stands on ends one step and starts the
// next); each resource is listed once.
function names(resourceSets) {
  return listed(new Set((resourceSets ?? []).flat()));
}

function listed(set) {
  return set.size === 0 ? '—' : [...set].join(', ');
}

function rows(body, cells) {
  body.replaceChildren(...cells.map((row) => {
    const tr = document.createElement('tr');
    row.forEach((cell) => {
      const td = document.createElement('td');
      td.textContent = cell;
      tr.append(td);
    });
    return tr;
  }));
}
