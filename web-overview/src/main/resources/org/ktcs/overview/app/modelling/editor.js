// The modelling mode: the plant view shows the model being edited (a Draft) instead of the running plant; the tool
// bar picks the tool; the side bar shows the properties of the selection and the model's problems. Every edit
// goes through edit(), so it can be undone, is kept as a local draft and is validated by the kernel.

import { Draft } from './draft.js';
import { KernelFiles } from './kernel-files.js';
import { PointerTool } from './pointer-tool.js';
import { EditOverlay } from './edit-overlay.js';
import { ModellingToolbar } from './toolbar.js';
import { PropertyPanel } from './property-panel.js';
import { installModellingKeys } from './keys.js';
import { ModelActions } from './model-actions.js';
import { LISTS } from './model-edits.js';
import { hiddenLayerIds } from './layer-edits.js';

const VALIDATE_DELAY_MS = 300;

export class ModellingMode {
  /**
   * @param {{plant: any, ktcs: any, client: any, toolbar: HTMLElement, panel: HTMLElement,
   *   onActiveChange: (active: boolean) => void}} parts
   */
  constructor({ plant, ktcs, client, toolbar, panel, onActiveChange }) {
    this.plant = plant;
    this.ktcs = ktcs;
    this.client = client;
    this.onActiveChange = onActiveChange;
    this.active = false;
    /** @type {Set<string>} "kind:name" keys of the selected elements */
    this.selection = new Set();
    this.tool = 'select';
    this.gridSize = 500;
    this.snapToGrid = true;
    this.activeLayer = 0;
    /** @type {import('./kernel-files.js').ModelProblem[]} */
    this.problems = [];
    this.problemsFor = null;
    this.files = new KernelFiles(client.accessKey);
    this.draft = new Draft((model) => this.modelChanged(model));
    this.pointer = new PointerTool(this);
    this.overlay = new EditOverlay(this);
    this.actions = new ModelActions(this);
    this.toolbar = new ModellingToolbar(toolbar, this);
    this.panel = new PropertyPanel(panel, this);
    installModellingKeys(this);
    window.addEventListener('pagehide', () => this.draft.writeLocalCopy());
  }

  /** Enters the modelling mode: with the unpublished edits of an earlier session, else with the kernel's model. */
  async enter() {
    if (this.active || this.entering) return;
    // The tools appear once the model is there, so that no edit lands on a model about to be replaced.
    this.entering = true;
    try {
      const stored = Draft.stored();
      if (!this.draft.model && stored) {
        this.draft.resume(stored);
        this.notify('Your unpublished edits are back (kept in this browser).');
      } else if (!this.draft.model) {
        const model = await this.ktcs.api('GET', '/plantModel');
        if (!this.draft.model) this.draft.open(model, 'kernel');
      }
    } finally {
      this.entering = false;
    }
    this.active = true;
    this.operatingHiddenLayers = this.plant.hiddenLayers;
    this.plant.tool = this;
    this.plant.vehicles.drawn.clear();
    this.onActiveChange(true);
    this.modelChanged(this.draft.model);
    this.plant.userMoved = false;
    this.plant.fit();
  }

  /** Back to operating: the plant view shows the running plant again; the draft stays for the next visit. */
  leave(runningModel) {
    if (!this.active) return;
    this.active = false;
    this.pointer.cancel();
    this.plant.tool = null;
    this.draft.writeLocalCopy();
    this.plant.hiddenLayers = this.operatingHiddenLayers ?? new Set();
    this.onActiveChange(false);
    if (runningModel) this.plant.setModel(runningModel);
    this.plant.invalidate();
  }

  setTool(tool) {
    this.pointer.cancel();
    this.tool = tool;
    this.toolbar.refresh();
  }

  snap(x, y) {
    if (!this.snapToGrid || !(this.gridSize > 0)) return { x: Math.round(x), y: Math.round(y) };
    return { x: Math.round(x / this.gridSize) * this.gridSize, y: Math.round(y / this.gridSize) * this.gridSize };
  }

  /** Applies an edit (a new model) and selects [selection] if given. */
  edit(model, selection = null) {
    if (selection) this.selection = new Set(selection);
    this.previewing = false;
    this.draft.apply(model);
  }

  /** Shows [model] (a move under way) without making it an edit; null shows the draft again. */
  preview(model) {
    this.previewing = Boolean(model);
    this.plant.setModel(model ?? this.draft.model);
  }

  select(keys) {
    this.selection = new Set(keys);
    this.selectionChanged();
  }

  toggle(key) {
    if (this.selection.has(key)) this.selection.delete(key);
    else this.selection.add(key);
    this.selectionChanged();
  }

  selectionChanged() {
    this.panel.refresh();
    this.toolbar.refresh();
    this.plant.requestFrame();
  }

  undo() {
    if (!this.draft.undo()) this.notify('Nothing to undo.');
  }

  redo() {
    if (!this.draft.redo()) this.notify('Nothing to redo.');
  }

  modelChanged(model) {
    const existing = this.existingKeys(model);
    this.selection = new Set([...this.selection].filter((key) => existing.has(key)));
    const layers = model.visualLayout?.layers ?? [];
    if (layers.length && !layers.some((l) => l.id === this.activeLayer)) this.activeLayer = layers[0].id;
    if (this.active) {
      // The model's own layer visibility (layer and group) decides what is drawn while it is edited.
      this.plant.hiddenLayers = hiddenLayerIds(model);
      this.plant.setModel(model);
    }
    this.panel.refresh();
    this.toolbar.refresh();
    this.scheduleValidation();
  }

  existingKeys(model) {
    const keys = new Set();
    for (const [kind, list] of Object.entries(LISTS)) {
      for (const element of model[list]) keys.add(`${kind}:${element.name}`);
    }
    return keys;
  }

  // The kernel validates; while edits come fast, only the latest model is sent.
  scheduleValidation() {
    clearTimeout(this.validationTimer);
    this.validationTimer = setTimeout(() => this.validate(), VALIDATE_DELAY_MS);
  }

  /** Validates the draft with the kernel; answers the problems (and shows them on the elements). */
  async validate() {
    clearTimeout(this.validationTimer);
    const model = this.draft.model;
    if (!model) return [];
    try {
      const { problems } = await this.files.validate(model);
      if (model === this.draft.model) {
        this.problems = problems;
        this.problemsFor = model;
        this.panel.refresh();
        this.plant.requestFrame();
      }
      return problems;
    } catch (error) {
      this.problems = [{ severity: 'ERROR', element: `model '${model.name}'`, name: model.name, message: error.message }];
      this.problemsFor = model;
      this.panel.refresh();
      return this.problems;
    }
  }

  notify(text, level = 'info') {
    this.ktcs.notify(text, level);
  }

  // The plant view's tool interface (see pointer-input.js and PlantView.drawOverlay).
  pointerDown(event) { this.pointer.pointerDown(event); }

  pointerMove(event) { this.pointer.pointerMove(event); }

  pointerUp(event) { this.pointer.pointerUp(event); }

  cancel() { this.pointer.cancel(); }

  drawOverlay(ctx) { this.overlay.draw(ctx); }
}
