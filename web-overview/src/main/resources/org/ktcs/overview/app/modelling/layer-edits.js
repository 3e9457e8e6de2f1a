// Edits of the model's layers and layer groups, as openTCS's Model Editor makes them: a layer is shown when it and
// its group are visible; deleting a layer deletes the elements on it, deleting a group deletes its layers; the last
// layer and the last group stay. Every edit answers a new model.

import { deleteElements } from './model-edits.js';

/** @typedef {{id: number, ordinal: number, visible: boolean, name: string, groupId: number}} Layer */
/** @typedef {{id: number, name: string, visible: boolean}} LayerGroup */

const DRAWN = { point: 'points', path: 'paths', location: 'locations' };

/**
 * @param {import('./model-edits.js').ModelJson} model
 * @returns {{layers: Layer[], layerGroups: LayerGroup[]}}
 */
function layoutOf(model) {
  return model.visualLayout;
}

/** @returns {import('./model-edits.js').ModelJson} */
function withLayout(model, change) {
  return { ...model, visualLayout: { ...model.visualLayout, ...change } };
}

/** The ids of the layers not shown: hidden themselves, or in a hidden group. */
export function hiddenLayerIds(model) {
  const { layers = [], layerGroups = [] } = layoutOf(model) ?? {};
  const groups = new Map(layerGroups.map((g) => [g.id, g]));
  return new Set(layers.filter((l) => !l.visible || groups.get(l.groupId)?.visible === false).map((l) => l.id));
}

/** The layers in their order (ordinal). */
export function orderedLayers(model) {
  return [...layoutOf(model).layers].sort((a, b) => a.ordinal - b.ordinal);
}

export function addLayer(model) {
  const { layers, layerGroups } = layoutOf(model);
  const id = Math.max(-1, ...layers.map((l) => l.id)) + 1;
  const ordinal = Math.max(-1, ...layers.map((l) => l.ordinal)) + 1;
  const groups = layerGroups.length ? layerGroups : [{ id: 0, name: 'Default layer group', visible: true }];
  const layer = { id, ordinal, visible: true, name: `Layer ${id}`, groupId: groups[0].id };
  return { model: withLayout(model, { layerGroups: groups, layers: [...layers, layer] }), id };
}

export function addLayerGroup(model) {
  const { layerGroups } = layoutOf(model);
  const id = Math.max(-1, ...layerGroups.map((g) => g.id)) + 1;
  return withLayout(model, { layerGroups: [...layerGroups, { id, name: `Layer group ${id}`, visible: true }] });
}

/** Layer [id] as [update] answers it. */
export function changeLayer(model, id, update) {
  return withLayout(model, { layers: layoutOf(model).layers.map((l) => (l.id === id ? update(l) : l)) });
}

/** Layer group [id] as [update] answers it. */
export function changeLayerGroup(model, id, update) {
  return withLayout(model, { layerGroups: layoutOf(model).layerGroups.map((g) => (g.id === id ? update(g) : g)) });
}

/** Layer [id] one place earlier ([by] -1) or later (+1) in the order: it swaps ordinals with its neighbour. */
export function moveLayer(model, id, by) {
  const ordered = orderedLayers(model);
  const at = ordered.findIndex((l) => l.id === id);
  const other = ordered[at + by];
  if (at < 0 || !other) return model;
  const ordinals = new Map([[id, other.ordinal], [other.id, ordered[at].ordinal]]);
  return withLayout(model, { layers: layoutOf(model).layers.map((l) => (ordinals.has(l.id) ? { ...l, ordinal: ordinals.get(l.id) } : l)) });
}

/** Deletes layers [ids] and the points, paths and locations on them (and what depends on those). */
export function deleteLayers(model, ids) {
  const keys = new Set();
  for (const [kind, list] of Object.entries(DRAWN)) {
    for (const element of model[list]) if (ids.has(element.layout?.layerId ?? 0)) keys.add(`${kind}:${element.name}`);
  }
  return withLayout(deleteElements(model, keys), { layers: layoutOf(model).layers.filter((l) => !ids.has(l.id)) });
}

/** Deletes layer group [id] with its layers; null if it is the last group or holds every layer. */
export function deleteLayerGroup(model, id) {
  const { layers, layerGroups } = layoutOf(model);
  const ids = new Set(layers.filter((l) => l.groupId === id).map((l) => l.id));
  if (layerGroups.length <= 1 || ids.size === layers.length) return null;
  const without = deleteLayers(model, ids);
  return withLayout(without, { layerGroups: layerGroups.filter((g) => g.id !== id) });
}

/** Puts the selected points, paths and locations ("kind:name" keys) on layer [layerId]. */
export function assignLayer(model, keys, layerId) {
  const change = {};
  for (const [kind, list] of Object.entries(DRAWN)) {
    change[list] = model[list].map((e) => (keys.has(`${kind}:${e.name}`) ? { ...e, layout: { ...e.layout, layerId } } : e));
  }
  return { ...model, ...change };
}
