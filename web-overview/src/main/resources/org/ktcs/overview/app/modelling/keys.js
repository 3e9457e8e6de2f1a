// The modelling mode's keyboard: tools (S, P, A, L), delete, undo/redo, copy/paste, and the arrow keys, which move
// the selection by one grid step (ten with shift). Keys typed into a field stay with the field.

const TOOL_KEYS = { s: 'select', p: 'point', a: 'path', l: 'location' };

/** @param {import('./editor.js').ModellingMode} editor */
export function installModellingKeys(editor) {
  document.addEventListener('keydown', (event) => {
    if (!editor.active || isTyping(event.target)) return;
    const key = event.key;
    const command = event.ctrlKey || event.metaKey;
    let handled = true;
    if (command && key.toLowerCase() === 'z') {
      if (event.shiftKey) editor.redo(); else editor.undo();
    } else if (command && key.toLowerCase() === 'y') {
      editor.redo();
    } else if (command && key.toLowerCase() === 'c') {
      editor.actions.copy();
    } else if (command && key.toLowerCase() === 'v') {
      editor.actions.paste();
    } else if (command && key.toLowerCase() === 'a') {
      editor.actions.selectAll();
    } else if (key === 'Delete' || key === 'Backspace') {
      editor.actions.deleteSelection();
    } else if (key === 'Escape') {
      editor.pointer.cancel();
      editor.select([]);
    } else if (key.startsWith('Arrow')) {
      const step = editor.gridSize * (event.shiftKey ? 10 : 1);
      const [dx, dy] = { ArrowLeft: [-step, 0], ArrowRight: [step, 0], ArrowUp: [0, step], ArrowDown: [0, -step] }[key];
      editor.actions.moveSelection(dx, dy);
    } else if (!command && !event.altKey && TOOL_KEYS[key.toLowerCase()]) {
      editor.setTool(TOOL_KEYS[key.toLowerCase()]);
    } else {
      handled = false;
    }
    if (handled) event.preventDefault();
  });
}

function isTyping(target) {
  return target instanceof HTMLElement && (target.isContentEditable || ['INPUT', 'SELECT', 'TEXTAREA'].includes(target.tagName));
}
