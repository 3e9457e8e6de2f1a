// The modelling mode's tool bar: tools, undo/redo, grid, and the model's open/save/publish actions.

import { el, fill } from '../dom.js';
import { helpButton } from './help.js';

const TOOLS = [
  ['select', 'Select', 'Select, move (drag), box-select (shift-drag) — key S'],
  ['point', 'Point', 'Click to place a point — key P'],
  ['path', 'Path / link', 'Click a point, then another: a path; a location and a point: a link — key A'],
  ['location', 'Location', 'Click to place a location — key L'],
];

export class ModellingToolbar {
  /**
   * @param {HTMLElement} root
   * @param {import('./editor.js').ModellingMode} editor
   */
  constructor(root, editor) {
    this.root = root;
    this.editor = editor;
    this.build();
  }

  build() {
    const editor = this.editor;
    const actions = editor.actions;
    this.toolButtons = TOOLS.map(([tool, label, title]) => el('button', {
      type: 'button', title, 'data-tool': tool, onclick: () => editor.setTool(tool),
    }, label));
    this.undoButton = el('button', { type: 'button', 'data-action': 'undo', title: 'Undo (Ctrl+Z)', onclick: () => editor.undo() }, 'Undo');
    this.redoButton = el('button', { type: 'button', 'data-action': 'redo', title: 'Redo (Ctrl+Y)', onclick: () => editor.redo() }, 'Redo');
    this.deleteButton = el('button', { type: 'button', 'data-action': 'delete', title: 'Delete the selection (Del)', onclick: () => actions.deleteSelection() }, 'Delete');
    const grid = el('input', {
      type: 'number', name: 'grid', min: '1', step: '100', value: String(editor.gridSize), title: 'Grid size in mm',
      className: 'grid-size',
      onchange: () => {
        const size = Number(grid.value);
        if (Number.isFinite(size) && size > 0) editor.gridSize = size;
        else grid.value = String(editor.gridSize);
      },
    });
    const snap = el('input', { type: 'checkbox', name: 'snap', checked: editor.snapToGrid, onchange: () => { editor.snapToGrid = snap.checked; } });
    const fileInput = el('input', { type: 'file', name: 'model-file', accept: '.xml,application/xml', hidden: true, onchange: () => actions.openFile(fileInput) });
    this.state = el('span', { className: 'draft-state' });
    fill(this.root,
      el('span', { className: 'tool-group', role: 'group', 'aria-label': 'Tools' }, this.toolButtons),
      this.undoButton, this.redoButton, this.deleteButton,
      el('label', { title: 'Snap new and moved elements to the grid' }, snap, ' Grid ', grid, ' mm'),
      el('span', { className: 'tool-group', role: 'group', 'aria-label': 'Model' },
        el('button', { type: 'button', 'data-action': 'new', title: 'Start an empty model', onclick: () => actions.newModel() }, 'New'),
        el('button', { type: 'button', 'data-action': 'open-file', title: 'Open an openTCS model file (any version)', onclick: () => fileInput.click() }, 'Open file…'),
        el('button', { type: 'button', 'data-action': 'open-kernel-model', title: 'Edit the model kTCS runs now', onclick: () => actions.openKernelModel(true) }, 'Open kernel model'),
        el('button', { type: 'button', 'data-action': 'save', title: 'Download as openTCS 7.0.0 XML', onclick: () => actions.save() }, 'Save'),
        el('button', { type: 'button', 'data-action': 'publish', className: 'primary', title: 'Make this the model kTCS runs (kept across restarts)', onclick: () => actions.publish() }, 'Publish')),
      helpButton(), fileInput, this.state);
    this.refresh();
  }

  refresh() {
    const editor = this.editor;
    for (const button of this.toolButtons) {
      const active = button.dataset.tool === editor.tool;
      button.classList.toggle('active', active);
      button.setAttribute('aria-pressed', String(active));
    }
    this.undoButton.disabled = editor.draft.undoStack.length === 0;
    this.redoButton.disabled = editor.draft.redoStack.length === 0;
    this.deleteButton.disabled = editor.selection.size === 0;
    const draft = editor.draft;
    this.state.textContent = draft.model ? `${draft.model.name}${draft.edited ? ' · unpublished edits' : ''}` : '';
  }
}
