// Layer visibility toggles and the plant summary line.

import { el, fill } from './dom.js';

export function installLayerToggles(container, model, plant) {
  const layers = [...(model.visualLayout?.layers ?? [])].sort((a, b) => a.ordinal - b.ordinal);
  const groups = new Map((model.visualLayout?.layerGroups ?? []).map((group) => [group.id, group]));
  fill(container, layers.length > 0 ? 'Layers:' : null, layers.map((layer) => {
    const visible = layer.visible && (groups.get(layer.groupId)?.visible ?? true);
    plant.setLayerVisible(layer.id, visible);
    return el('label', { title: `Layer group: ${groups.get(layer.groupId)?.name ?? '—'}` }, el('input', {
      type: 'checkbox', checked: visible, 'data-layer': layer.id,
      onchange: (event) => plant.setLayerVisible(layer.id, event.target.checked),
    }), ` ${layer.name}`);
  }));
}

export function summaryOf(model) {
  return `${model.points.length} points · ${model.paths.length} paths · ${model.locations.length} locations · ` +
    `${model.vehicles.length} vehicles`;
}
