// The model being edited, with undo/redo of every edit and a local copy that survives a page reload. Models are
// never changed in place (see model-edits.js), so the history holds whole models and shares what did not change.

const STORAGE_KEY = 'ktcs.modelling.draft';
const MAX_HISTORY = 200;
const SAVE_DELAY_MS = 400;

/** @typedef {import('./model-edits.js').ModelJson} ModelJson */

export class Draft {
  /** @param {(model: ModelJson) => void} onChange called after every change of the model (edit, undo, redo, open) */
  constructor(onChange) {
    this.onChange = onChange;
    /** @type {ModelJson|null} */
    this.model = null;
    /** @type {ModelJson[]} */
    this.undoStack = [];
    /** @type {ModelJson[]} */
    this.redoStack = [];
    /** Where the model came from ("kernel", a file name, "draft", "new") and whether it has unpublished edits. */
    this.origin = '';
    this.edited = false;
    this.saveTimer = 0;
  }

  /** Starts over with [model] (opened from the kernel or a file): no history, no unpublished edits. */
  open(model, origin) {
    this.model = model;
    this.origin = origin;
    this.undoStack = [];
    this.redoStack = [];
    this.edited = false;
    this.forgetLocalCopy();
    this.onChange(model);
  }

  /** The local copy of an earlier session's unpublished edits, or null. */
  static stored() {
    try {
      const text = localStorage.getItem(STORAGE_KEY);
      return text ? JSON.parse(text) : null;
    } catch {
      return null;
    }
  }

  /** Takes up an earlier session's unpublished edits. */
  resume(stored) {
    this.open(stored.model, stored.origin);
    this.edited = true;
    this.keepLocally();
  }

  /** Applies an edit: [model] replaces the current one, which goes onto the undo stack. */
  apply(model) {
    if (!model || model === this.model) return;
    this.undoStack.push(this.model);
    if (this.undoStack.length > MAX_HISTORY) this.undoStack.shift();
    this.redoStack = [];
    this.changed(model);
  }

  undo() {
    const previous = this.undoStack.pop();
    if (!previous) return false;
    this.redoStack.push(this.model);
    this.changed(previous);
    return true;
  }

  redo() {
    const next = this.redoStack.pop();
    if (!next) return false;
    this.undoStack.push(this.model);
    this.changed(next);
    return true;
  }

  /** The model was published: what the kernel runs now is this model. */
  published() {
    this.edited = false;
    this.origin = 'kernel';
    this.forgetLocalCopy();
  }

  changed(model) {
    this.model = model;
    this.edited = true;
    this.keepLocally();
    this.onChange(model);
  }

  // Writing a large model on every drag step would stall the page; the latest state is written once edits pause.
  keepLocally() {
    clearTimeout(this.saveTimer);
    this.saveTimer = setTimeout(() => this.writeLocalCopy(), SAVE_DELAY_MS);
  }

  /** Writes the local copy now (also when the page is left). */
  writeLocalCopy() {
    clearTimeout(this.saveTimer);
    if (!this.edited || !this.model) return;
    try {
      localStorage.setItem(STORAGE_KEY, JSON.stringify({ model: this.model, origin: this.origin, savedAt: Date.now() }));
    } catch (error) {
      console.warn('the draft could not be kept in this browser', error);
    }
  }

  forgetLocalCopy() {
    clearTimeout(this.saveTimer);
    localStorage.removeItem(STORAGE_KEY);
  }
}
