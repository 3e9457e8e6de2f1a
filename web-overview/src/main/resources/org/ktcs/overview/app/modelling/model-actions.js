// The modelling mode's commands on the whole model and the selection: open, save, publish, delete, copy/paste,
// move by keys, add the elements that are not placed on the plant (vehicles, location types, blocks, layers).

import {
  addBlock, addLocationType, addVehicle, deleteElements, emptyModel, moveElements, recomputeLengths,
} from './model-edits.js';
import { pasteCopies } from './copies.js';

const PUBLISH_RETRIES = 20;

export class ModelActions {
  /** @param {import('./editor.js').ModellingMode} editor */
  constructor(editor) {
    this.editor = editor;
    this.clipboard = null;
    this.pastes = 0;
  }

  get draft() { return this.editor.draft; }

  /** Unpublished edits are only dropped when the user agrees. */
  mayDiscard() {
    return !this.draft.edited || window.confirm('Discard the unpublished edits of this model?');
  }

  async openKernelModel(ask = false) {
    if (ask && !this.mayDiscard()) return;
    const model = await this.editor.ktcs.api('GET', '/plantModel');
    this.editor.selection.clear();
    this.draft.open(model, 'kernel');
    this.editor.plant.userMoved = false;
    this.editor.plant.fit();
  }

  newModel() {
    if (!this.mayDiscard()) return;
    this.editor.selection.clear();
    this.draft.open(emptyModel(), 'new');
  }

  /** Opens an openTCS file of any version the kernel reads; the reader's warnings are shown. */
  async openFile(input) {
    const file = input.files?.[0];
    input.value = '';
    if (!file || !this.mayDiscard()) return;
    try {
      const { model, warnings } = await this.editor.files.read(await file.text());
      this.editor.selection.clear();
      this.draft.open(model, file.name);
      this.editor.plant.userMoved = false;
      this.editor.plant.fit();
      const note = warnings.length ? ` (${warnings.length} warning(s): ${warnings[0].message}${warnings.length > 1 ? ', …' : ''})` : '';
      this.editor.notify(`Opened ${file.name}${note}`);
    } catch (error) {
      this.editor.notify(`${file.name} could not be opened: ${error.message}`, 'error');
    }
  }

  /** Downloads the model as openTCS 7.0.0 XML, written by the kernel's writer. */
  async save() {
    try {
      const xml = await this.editor.files.write(this.draft.model);
      const link = document.createElement('a');
      link.href = URL.createObjectURL(new Blob([xml], { type: 'application/xml' }));
      link.download = `${this.draft.model.name.replace(/[^\w.-]+/g, '_') || 'plant-model'}.xml`;
      document.body.append(link);
      link.click();
      link.remove();
      setTimeout(() => URL.revokeObjectURL(link.href), 10_000);
    } catch (error) {
      this.editor.notify(`The model could not be saved: ${error.message}`, 'error');
    }
  }

  /**
   * Publishes the model: refused with the list while it has errors; while kTCS processes orders it offers to
   * withdraw them first.
   */
  async publish() {
    const editor = this.editor;
    const problems = await editor.validate();
    const errors = problems.filter((p) => p.severity === 'ERROR');
    if (errors.length > 0) {
      editor.panel.showProblems();
      editor.notify(`Not published: the model has ${errors.length} error(s): ${errors.slice(0, 3).map((e) => `${e.element}: ${e.message}`).join('; ')}`, 'error');
      return false;
    }
    try {
      await editor.files.publish(this.draft.model);
    } catch (error) {
      if (error.status !== 409) {
        editor.notify(`Not published: ${error.message}`, 'error');
        return false;
      }
      if (!window.confirm(`kTCS refused: ${error.message}\n\nWithdraw all transport orders and publish?`)) return false;
      if (!await this.withdrawAllAndPublish()) return false;
    }
    this.draft.published();
    editor.toolbar.refresh();
    editor.notify(`Published: kTCS runs "${this.draft.model.name}" now, and will after a restart.`);
    return true;
  }

  async withdrawAllAndPublish() {
    const { ktcs } = this.editor;
    const orders = await ktcs.api('GET', '/transportOrders');
    await Promise.all(orders.filter((o) => !['FINISHED', 'FAILED', 'UNROUTABLE'].includes(o.state))
      .map((o) => ktcs.api('POST', `/transportOrders/${encodeURIComponent(o.name)}/withdrawal?immediate=true`)));
    // Vehicles finish the movement they are on before kTCS agrees.
    for (let attempt = 0; attempt < PUBLISH_RETRIES; attempt += 1) {
      try {
        await this.editor.files.publish(this.draft.model);
        return true;
      } catch (error) {
        if (error.status !== 409 || attempt === PUBLISH_RETRIES - 1) {
          this.editor.notify(`Not published: ${error.message}`, 'error');
          return false;
        }
        await new Promise((resolve) => setTimeout(resolve, 500));
      }
    }
    return false;
  }

  deleteSelection() {
    const editor = this.editor;
    if (editor.selection.size === 0) return;
    editor.edit(deleteElements(this.draft.model, editor.selection), []);
  }

  selectAll() {
    const model = this.draft.model;
    this.editor.select([...model.points.map((p) => `point:${p.name}`), ...model.paths.map((p) => `path:${p.name}`),
      ...model.locations.map((l) => `location:${l.name}`)]);
  }

  copy() {
    if (this.editor.selection.size === 0) return;
    this.clipboard = { model: this.draft.model, keys: new Set(this.editor.selection) };
    this.pastes = 0;
  }

  /** Pastes copies of the copied elements; points and locations one grid step further each time. */
  paste() {
    if (!this.clipboard) return;
    this.pastes += 1;
    const offset = Math.max(this.editor.gridSize, 500) * this.pastes;
    const pasted = pasteCopies(this.draft.model, this.clipboard.model, this.clipboard.keys, offset, -offset);
    if (pasted.keys.size === 0) {
      this.editor.notify('Nothing to paste: a path is copied with the points at both its ends (select them too).');
      return;
    }
    this.editor.edit(pasted.model, [...pasted.keys]);
  }

  moveSelection(dx, dy) {
    const editor = this.editor;
    const movable = [...editor.selection].some((k) => k.startsWith('point:') || k.startsWith('location:'));
    if (movable) editor.edit(moveElements(this.draft.model, editor.selection, dx, dy));
  }

  /** Recomputes path lengths from the geometry: the selected paths, or all when none is selected. */
  recomputeLengths() {
    const names = [...this.editor.selection].filter((k) => k.startsWith('path:')).map((k) => k.slice(5));
    this.editor.edit(recomputeLengths(this.draft.model, names.length ? new Set(names) : null));
  }

  add(kind) {
    const model = this.draft.model;
    const members = [...this.editor.selection].map((k) => k.slice(k.indexOf(':') + 1));
    const added = { vehicle: () => addVehicle(model), locationType: () => addLocationType(model),
      block: () => addBlock(model, members) }[kind]();
    this.editor.edit(added.model, [`${kind}:${added.name}`]);
  }
}
