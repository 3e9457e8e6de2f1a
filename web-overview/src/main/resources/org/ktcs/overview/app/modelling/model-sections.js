// Parts of the modelling side bar about the whole model: its layers and layer groups, and the validator's problems.

import { el } from '../dom.js';
import { LISTS } from './model-edits.js';
import {
  addLayer, addLayerGroup, changeLayer, changeLayerGroup, deleteLayerGroup, deleteLayers, moveLayer, orderedLayers,
} from './layer-edits.js';

/**
 * The layers in their order (the active one gets new elements) with visibility, name, group, order and deletion, and
 * the layer groups with visibility, name and deletion.
 */
export function layersSection(editor) {
  const model = editor.draft.model;
  const { layers, layerGroups } = model.visualLayout;
  const edit = (next) => next && editor.edit(next);
  const ordered = orderedLayers(model);
  const onLayer = (id) => ['points', 'paths', 'locations'].reduce((n, list) => n + model[list].filter((e) => (e.layout?.layerId ?? 0) === id).length, 0);
  const removeLayer = (layer) => {
    const count = onLayer(layer.id);
    if (count && !window.confirm(`Delete layer "${layer.name}" and the ${count} element(s) on it?`)) return;
    if (editor.activeLayer === layer.id) editor.activeLayer = ordered.find((l) => l.id !== layer.id).id;
    edit(deleteLayers(model, new Set([layer.id])));
  };
  const removeGroup = (group) => {
    if (!window.confirm(`Delete layer group "${group.name}" with its layers and their elements?`)) return;
    const next = deleteLayerGroup(model, group.id);
    if (!next) return editor.notify('The last layer group, and a group holding every layer, stay.', 'error');
    if (!next.visualLayout.layers.some((l) => l.id === editor.activeLayer)) editor.activeLayer = next.visualLayout.layers[0].id;
    edit(next);
  };
  const rows = ordered.map((layer, i) => el('li', { 'data-layer': String(layer.id) },
    el('input', { type: 'radio', name: 'active-layer', checked: layer.id === editor.activeLayer, title: 'New elements go to this layer',
      onchange: () => { editor.activeLayer = layer.id; } }),
    el('input', { type: 'checkbox', name: 'layer-visible', checked: layer.visible, title: 'Visible',
      onchange: (event) => edit(changeLayer(model, layer.id, (l) => ({ ...l, visible: event.target.checked }))) }),
    el('input', { type: 'text', value: layer.name, name: `layer-${layer.id}`, onchange: (event) => edit(changeLayer(model, layer.id, (l) => ({ ...l, name: event.target.value }))) }),
    el('select', { title: 'Layer group', onchange: (event) => edit(changeLayer(model, layer.id, (l) => ({ ...l, groupId: Number(event.target.value) }))) },
      layerGroups.map((g) => el('option', { value: String(g.id), selected: g.id === layer.groupId }, g.name))),
    el('button', { type: 'button', title: 'Earlier in the order', disabled: i === 0, onclick: () => edit(moveLayer(model, layer.id, -1)) }, '↑'),
    el('button', { type: 'button', title: 'Later in the order', disabled: i === ordered.length - 1, onclick: () => edit(moveLayer(model, layer.id, 1)) }, '↓'),
    el('button', { type: 'button', 'data-action': 'delete-layer', title: 'Delete the layer and its elements', disabled: layers.length <= 1, onclick: () => removeLayer(layer) }, '×')));
  const groups = layerGroups.map((group) => el('li', { 'data-layer-group': String(group.id) },
    el('input', { type: 'checkbox', name: 'layer-group-visible', checked: group.visible, title: 'Visible (with its layers)',
      onchange: (event) => edit(changeLayerGroup(model, group.id, (g) => ({ ...g, visible: event.target.checked }))) }),
    el('input', { type: 'text', value: group.name, name: `layer-group-${group.id}`,
      onchange: (event) => edit(changeLayerGroup(model, group.id, (g) => ({ ...g, name: event.target.value }))) }),
    el('button', { type: 'button', 'data-action': 'delete-layer-group', title: 'Delete the group, its layers and their elements', disabled: layerGroups.length <= 1, onclick: () => removeGroup(group) }, '×')));
  const addNewLayer = () => {
    const added = addLayer(model);
    editor.activeLayer = added.id;
    edit(added.model);
  };
  return el('section', { className: 'element-list layer-list' },
    el('h4', {}, 'Layers ', el('button', { type: 'button', 'data-add': 'layer', onclick: addNewLayer }, 'Add')), el('ul', {}, rows),
    el('h4', {}, 'Layer groups ', el('button', { type: 'button', 'data-add': 'layer-group', onclick: () => edit(addLayerGroup(model)) }, 'Add')), el('ul', {}, groups));
}

/** The validator's errors and warnings (of [key]'s element only, if given); a click selects the element. */
export function problemsSection(editor, key = null) {
  const name = key ? key.slice(key.indexOf(':') + 1) : null;
  const current = editor.problemsFor === editor.draft.model;
  const problems = editor.problems.filter((p) => !name || p.name === name);
  const errors = problems.filter((p) => p.severity === 'ERROR').length;
  const title = !current ? 'Checking…' : problems.length === 0 ? 'No problems' : `${errors} error(s), ${problems.length - errors} warning(s)`;
  return el('section', { className: 'problems', 'aria-live': 'polite' }, el('h4', {}, title),
    el('ul', {}, problems.slice(0, 200).map((p) => el('li', { className: `problem ${p.severity.toLowerCase()}` },
      el('button', { type: 'button', className: 'link', onclick: () => selectNamed(editor, p.name) }, p.element),
      `: ${p.message}`))));
}

function selectNamed(editor, name) {
  if (!name) return;
  const model = editor.draft.model;
  for (const [kind, list] of Object.entries(LISTS)) {
    if (model[list].some((e) => e.name === name)) return editor.select([`${kind}:${name}`]);
  }
}
