// The side bar of the modelling mode: the properties of the selected element in typed fields (checked as typed,
// applied on change, undoable), or, with nothing selected, the model's elements that are not drawn (vehicles,
// location types, blocks, layers) and its problems.

import { el, fill } from '../dom.js';
import { FIELDS, nameProblem } from './element-fields.js';
import { LISTS, renameElement, replaceNamed } from './model-edits.js';
import { layersSection, problemsSection } from './model-sections.js';
import { assignLayer } from './layer-edits.js';
import { orderTypesView } from './order-types.js';

const KIND_TITLES = { point: 'Point', path: 'Path', location: 'Location', locationType: 'Location type', block: 'Block', vehicle: 'Vehicle' };

export class PropertyPanel {
  /**
   * @param {HTMLElement} root
   * @param {import('./editor.js').ModellingMode} editor
   */
  constructor(root, editor) {
    this.root = root;
    this.editor = editor;
    // A committed value leaves its field, so the panel may show the result (it is not rebuilt under typing).
    root.addEventListener('change', (event) => {
      if (event.target instanceof HTMLInputElement && event.target.type !== 'checkbox') event.target.blur();
    }, true);
  }

  get model() { return this.editor.draft.model; }

  refresh() {
    // A field being typed into is not rebuilt under the user's fingers.
    if (this.root.contains(document.activeElement) && document.activeElement.matches('input[type=text], input[type=number]')) return;
    if (!this.model) return fill(this.root);
    const keys = [...this.editor.selection];
    if (keys.length === 1) return fill(this.root, this.elementView(keys[0]), problemsSection(this.editor, keys[0]));
    if (keys.length > 1) return fill(this.root, this.multipleView(keys), problemsSection(this.editor));
    return fill(this.root, this.modelView(), problemsSection(this.editor));
  }

  showProblems() {
    this.editor.select([]);
    this.root.querySelector('.problems')?.scrollIntoView({ block: 'nearest' });
  }

  elementView(key) {
    const kind = key.slice(0, key.indexOf(':'));
    const name = key.slice(kind.length + 1);
    const element = this.model[LISTS[kind]].find((e) => e.name === name);
    if (!element) return el('p', {}, 'Nothing selected.');
    const change = (update) => this.editor.edit(replaceNamed(this.model, kind, name, update));
    const nameField = this.field({
      key: 'name', label: 'Name', type: 'text', get: (e) => e.name,
      check: (v) => nameProblem(v, name, this.model),
    }, element, (value) => this.editor.edit(renameElement(this.model, kind, name, value), [`${kind}:${value}`]));
    return el('form', { className: 'properties', 'data-kind': kind, onsubmit: (event) => event.preventDefault() },
      el('h3', {}, KIND_TITLES[kind]),
      nameField,
      FIELDS[kind].map((field) => this.field(field, element, (value) => change((e) => field.set(e, value, this.model)))),
      kind === 'path' ? el('button', { type: 'button', onclick: () => this.editor.actions.recomputeLengths() }, 'Recompute length') : null,
      kind === 'location' ? this.linksView(element, change) : null,
      kind === 'vehicle' ? orderTypesView(this.editor, element.name) : null,
      el('button', { type: 'button', 'data-action': 'duplicate', title: 'Copy and paste (Ctrl+C, Ctrl+V)',
        onclick: () => { this.editor.actions.copy(); this.editor.actions.paste(); } }, 'Duplicate'),
      this.propertiesView(element, change));
  }

  /** One labelled input; invalid values are shown as such and not applied. */
  field(field, element, apply) {
    const value = field.get(element);
    const message = el('span', { className: 'field-error', role: 'alert' });
    const attrs = { name: field.key, disabled: field.readOnly };
    let input;
    if (field.type === 'select') {
      const options = field.options(this.model);
      input = el('select', attrs, [...new Set([String(value ?? ''), ...options])].filter(Boolean).map((o) => el('option', { value: o, selected: o === String(value) }, field.optionLabel?.(this.model, o) ?? o)));
    } else if (field.type === 'checkbox') {
      input = el('input', { ...attrs, type: 'checkbox', checked: Boolean(value) });
    } else {
      input = el('input', { ...attrs, type: field.type === 'number' ? 'number' : field.type === 'color' ? 'color' : 'text', value: String(value ?? '') });
    }
    const read = () => (field.type === 'checkbox' ? input.checked : field.type === 'number' ? (input.value === '' ? NaN : Number(input.value)) : input.value);
    const problem = () => field.check?.(read(), element, this.model) ?? null;
    input.addEventListener('input', () => {
      const found = problem();
      message.textContent = found ? `${field.label} ${found}` : '';
      input.classList.toggle('invalid', Boolean(found));
      input.setAttribute('aria-invalid', String(Boolean(found)));
    });
    input.addEventListener('change', () => {
      if (problem()) return;
      if (read() !== value) apply(read());
    });
    return el('label', { className: `field field-${field.type}` }, el('span', {}, field.label), input, message);
  }

  linksView(location, change) {
    const type = this.model.locationTypes.find((t) => t.name === location.typeName);
    const rows = location.links.map((link, i) => el('li', {},
      el('span', {}, link.pointName),
      el('input', {
        type: 'text', name: `link-${link.pointName}`, value: link.allowedOperations.join(', '),
        placeholder: type ? `all of the type's (${type.allowedOperations.join(', ')})` : 'operations',
        title: 'Operations allowed at this link (comma-separated; empty: those of the location type)',
        onchange: (event) => change((l) => ({ ...l, links: l.links.map((k, j) => (j === i
          ? { ...k, allowedOperations: event.target.value.split(',').map((s) => s.trim()).filter(Boolean) } : k)) })),
      }),
      el('button', { type: 'button', title: 'Remove the link', onclick: () => change((l) => ({ ...l, links: l.links.filter((_, j) => j !== i) })) }, '×')));
    return el('section', { className: 'links' }, el('h4', {}, 'Links'),
      rows.length ? el('ul', {}, rows) : el('p', { className: 'hint' }, 'No link. Use the Path / link tool: click the location, then a point.'));
  }

  /** The element's key/value properties: edit, remove, add. */
  propertiesView(element, change) {
    const properties = element.properties ?? [];
    const setAt = (i, property) => change((e) => ({ ...e, properties: property
      ? properties.map((p, j) => (j === i ? property : p)) : properties.filter((_, j) => j !== i) }));
    const key = el('input', { type: 'text', name: 'new-property-key', placeholder: 'key' });
    const value = el('input', { type: 'text', name: 'new-property-value', placeholder: 'value' });
    const add = () => {
      if (!key.value.trim()) return;
      change((e) => ({ ...e, properties: [...properties.filter((p) => p.name !== key.value.trim()), { name: key.value.trim(), value: value.value }] }));
    };
    return el('section', { className: 'element-properties' }, el('h4', {}, 'Properties'),
      el('table', {}, el('tbody', {}, properties.map((p, i) => el('tr', {},
        el('td', {}, p.name),
        el('td', {}, el('input', { type: 'text', value: p.value, name: `property-${p.name}`, onchange: (event) => setAt(i, { ...p, value: event.target.value }) })),
        el('td', {}, el('button', { type: 'button', title: 'Remove', onclick: () => setAt(i, null) }, '×')))))),
      el('div', { className: 'add-property' }, key, value, el('button', { type: 'button', onclick: add }, 'Add')));
  }

  multipleView(keys) {
    const actions = this.editor.actions;
    return el('section', { className: 'properties' }, el('h3', {}, `${keys.length} elements selected`),
      el('p', { className: 'hint' }, 'Drag or use the arrow keys to move them; Ctrl+C / Ctrl+V to copy.'),
      this.layerChoice(keys),
      el('button', { type: 'button', onclick: () => actions.add('block') }, 'New block of the selection'),
      el('button', { type: 'button', onclick: () => actions.recomputeLengths() }, 'Recompute path lengths'),
      el('button', { type: 'button', onclick: () => actions.deleteSelection() }, 'Delete'));
  }

  /** A choice of layer that puts the selected points, paths and locations on it. */
  layerChoice(keys) {
    const model = this.model;
    const drawn = keys.filter((k) => /^(point|path|location):/.test(k));
    if (drawn.length === 0) return null;
    const layerIds = new Set(drawn.map((k) => {
      const kind = k.slice(0, k.indexOf(':'));
      return model[LISTS[kind]].find((e) => e.name === k.slice(kind.length + 1))?.layout?.layerId ?? 0;
    }));
    const current = layerIds.size === 1 ? [...layerIds][0] : null;
    return el('label', { className: 'field field-select' }, el('span', {}, 'Layer'),
      el('select', { name: 'selection-layer', onchange: (event) => this.editor.edit(assignLayer(model, new Set(drawn), Number(event.target.value))) },
        current === null ? el('option', { value: '', selected: true, disabled: true }, '(several)') : null,
        model.visualLayout.layers.map((l) => el('option', { value: String(l.id), selected: l.id === current }, l.name))));
  }

  modelView() {
    const model = this.model;
    const actions = this.editor.actions;
    const nameField = this.field({ key: 'model-name', label: 'Model name', type: 'text', get: (m) => m.name,
      check: (v) => (v.trim() ? null : 'must not be empty') }, model, (value) => this.editor.edit({ ...model, name: value }));
    const listOf = (kind, title) => el('section', { className: `element-list list-${kind}` },
      el('h4', {}, title, ' ', el('button', { type: 'button', 'data-add': kind, onclick: () => actions.add(kind) }, 'Add')),
      el('ul', {}, model[LISTS[kind]].map((e) => el('li', {},
        el('button', { type: 'button', className: 'link', onclick: () => this.editor.select([`${kind}:${e.name}`]) }, e.name)))));
    return el('section', { className: 'properties model' }, el('h3', {}, 'Model'), nameField,
      el('p', { className: 'summary' }, `${model.points.length} points · ${model.paths.length} paths · ${model.locations.length} locations`),
      el('button', { type: 'button', onclick: () => actions.recomputeLengths() }, 'Recompute all path lengths'),
      listOf('vehicle', 'Vehicles'), listOf('locationType', 'Location types'), listOf('block', 'Blocks'),
      layersSection(this.editor), this.propertiesView(model, (update) => this.editor.edit(update(model))));
  }
}
