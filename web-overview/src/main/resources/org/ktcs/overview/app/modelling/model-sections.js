// Parts of the modelling side bar about the whole model: its layers and layer groups, and the validator's problems.

import { el } from '../dom.js';
import { LISTS } from './model-edits.js';

/** The layers (the active one gets new elements) and layer groups, with visibility, name and group. */
export function layersSection(editor) {
  const model = editor.draft.model;
  const layout = model.visualLayout;
  const change = (visualLayout) => editor.edit({ ...model, visualLayout });
  const setLayer = (id, update) => change({ ...layout, layers: layout.layers.map((l) => (l.id === id ? update(l) : l)) });
  const addLayer = () => {
    const id = Math.max(-1, ...layout.layers.map((l) => l.id)) + 1;
    const group = layout.layerGroups[0]?.id ?? 0;
    const groups = layout.layerGroups.length ? layout.layerGroups : [{ id: 0, name: 'Default layer group', visible: true }];
    change({ ...layout, layerGroups: groups, layers: [...layout.layers, { id, ordinal: id, visible: true, name: `Layer ${id}`, groupId: group }] });
  };
  const addGroup = () => {
    const id = Math.max(-1, ...layout.layerGroups.map((g) => g.id)) + 1;
    change({ ...layout, layerGroups: [...layout.layerGroups, { id, name: `Layer group ${id}`, visible: true }] });
  };
  const rows = layout.layers.map((layer) => el('li', {},
    el('input', { type: 'radio', name: 'active-layer', checked: layer.id === editor.activeLayer, title: 'New elements go to this layer',
      onchange: () => { editor.activeLayer = layer.id; } }),
    el('input', { type: 'checkbox', checked: layer.visible, title: 'Visible', onchange: (event) => setLayer(layer.id, (l) => ({ ...l, visible: event.target.checked })) }),
    el('input', { type: 'text', value: layer.name, name: `layer-${layer.id}`, onchange: (event) => setLayer(layer.id, (l) => ({ ...l, name: event.target.value })) }),
    el('select', { title: 'Layer group', onchange: (event) => setLayer(layer.id, (l) => ({ ...l, groupId: Number(event.target.value) })) },
      layout.layerGroups.map((g) => el('option', { value: String(g.id), selected: g.id === layer.groupId }, g.name)))));
  const groups = layout.layerGroups.map((group) => el('li', {},
    el('input', { type: 'text', value: group.name, name: `layer-group-${group.id}`,
      onchange: (event) => change({ ...layout, layerGroups: layout.layerGroups.map((g) => (g.id === group.id ? { ...g, name: event.target.value } : g)) }) })));
  return el('section', { className: 'element-list layers' },
    el('h4', {}, 'Layers ', el('button', { type: 'button', onclick: addLayer }, 'Add')), el('ul', {}, rows),
    el('h4', {}, 'Layer groups ', el('button', { type: 'button', onclick: addGroup }, 'Add')), el('ul', {}, groups));
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
