// A panel listing every vehicle with its energy and order, kept up to date from the "vehicles" topic,
// to show what a panel can do with the ktcs object (see docs/developers-guide.md).
import { energyColour } from "./energy.js";

// snippet:panel-rows
/** The table rows for the vehicles known so far, by name: [name, energy text, colour, order]. */
export function energyRows(vehiclesByName) {
  return [...vehiclesByName.values()]
    .sort((a, b) => a.name.localeCompare(b.name))
    .map((vehicle) => [vehicle.name, `${vehicle.energyLevel}%`, energyColour(vehicle), vehicle.transportOrder ?? "–"]);
}
// end-snippet

function render(table, vehiclesByName) {
  table.replaceChildren(
    ...energyRows(vehiclesByName).map(([name, energy, colour, order]) => {
      const row = document.createElement("tr");
      for (const text of [name, energy, order]) {
        const cell = document.createElement("td");
        cell.textContent = text;
        row.append(cell);
      }
      row.children[1].style.color = colour;
      return row;
    }),
  );
}

// snippet:panel-mount
export default {
  mount(container, ktcs) {
    const vehiclesByName = new Map();
    const table = document.createElement("table");
    container.append(table);
    const unsubscribe = ktcs.subscribe("vehicles", (message) => {
      if (message.type === "snapshot") {
        vehiclesByName.clear();
        message.objects.forEach((vehicle) => vehiclesByName.set(vehicle.name, vehicle));
      } else if (message.type === "event") {
        vehiclesByName.set(message.current.name, message.current);
      }
      render(table, vehiclesByName);
    });
    return () => {
      unsubscribe();
      table.remove();
    };
  },
};
// end-snippet
