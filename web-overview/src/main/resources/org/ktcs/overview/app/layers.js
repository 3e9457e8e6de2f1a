// Layer visibility toggles and the plant summary line.

import { el, fill } from './dom.js';

export function installLayerToggles(container, model, plant) {
  const layers = [...(model.visualLayout?.layers ?? [])].sort((a, b) => a.ordinal - b.ordinal);
  if (layers.length <= 1 && !layers.some((layer) => !layer.visible)) {
    fill(container);
    layers.forEach((layer) => plant.setLayerVisible(layer.id, layer.visible));
    return;
  }
  fill(container, 'Layers:', layers.map((layer) => {
    plant.setLayerVisible(layer.id, layer.visible);
    return el('label', {}, el('input', {
      type: 'checkbox', checked: layer.visible, onchange: (event) => plant.setLayerVisible(layer.id, event.target.checked),
    }), ` ${layer.name}`);
  }));
}

export function summaryOf(model) {
  return `${model.points.length} points · ${model.paths.length} paths · ${model.locations.length} locations · ` +
    `${model.vehicles.length} vehicles`;
}
