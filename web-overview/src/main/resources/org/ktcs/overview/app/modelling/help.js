// The modelling mode's help: how to draw, edit, check and publish a plant, in a dialog.

import { el } from '../dom.js';

const TOPICS = [
  ['Draw', 'Pick a tool (or press its key) and click the plant. Point (P) places a point, Location (L) a location, ' +
    'both on the grid when Grid is ticked. Path / link (A): click a point, then another, for a path from the first ' +
    'to the second; click a location, then a point, to link them. Vehicles, location types and blocks are added in ' +
    'the side bar (with nothing selected); a block takes the selection as its members.'],
  ['Select and move', 'Select (S): click an element; shift-click adds or removes; shift-drag a box. Drag the ' +
    'selection, or move it with the arrow keys (one grid step, ten with shift). Drag empty space to pan, scroll to ' +
    'zoom. Ctrl+A selects all; Delete removes the selection and what depends on it. Ctrl+C / Ctrl+V (or Duplicate) ' +
    'copy and paste any element: points and locations with the paths and links between them, paths, and vehicles, ' +
    'location types and blocks picked in the side bar. Copies get the next free names (Point-0009, Vehicle-0002).'],
  ['Properties', 'The side bar shows the selection\'s properties in typed fields: a value that is not allowed is ' +
    'marked as you type and not applied. Renaming updates every reference. Path lengths are recomputed from the ' +
    'drawing on request (Recompute length), as in openTCS. Key/value properties of every element are at the end ' +
    '(e.g. loopback:initialPosition on a vehicle to start it on a point). A vehicle\'s acceptable order types ' +
    '(Transport:0, Park:1; * for any) belong to the running vehicle, as in openTCS: they are saved at once.'],
  ['Paths', 'Connection types are drawn as in openTCS: ELBOW as a right-angled dog-leg, SLANTED with a short ' +
    'horizontal stub at each end, POLYPATH through its control points, BEZIER (two) and BEZIER_3 (five) as curves. ' +
    'A new curve gets its control points along the line; drag their square handles to bend it.'],
  ['Layers', 'With nothing selected the side bar lists the layers and layer groups: add, rename, reorder, hide or ' +
    'show (a layer shows when it and its group do), delete (with the elements on it). New elements go to the ' +
    'active layer (its radio button); a selection is put on a layer with its Layer field.'],
  ['Undo, check, keep', 'Every edit can be undone (Ctrl+Z) and redone (Ctrl+Y). The kernel checks the model as you ' +
    'edit: errors are ringed red on the plant, warnings amber, and listed in the side bar. Edits that are not ' +
    'published are kept in this browser and come back after a reload.'],
  ['Open, save, publish', 'Open file… reads an openTCS model file of any version; Open kernel model edits the model ' +
    'kTCS runs; Save downloads the model as an openTCS 7.0.0 file. Publish makes the model the one kTCS runs, and ' +
    'the one it starts with next time. It is refused while the model has errors. While orders run, kTCS refuses it ' +
    'too (unless only locks and velocities changed); the page then offers to withdraw the orders first.'],
];

/** A Help button that opens the modelling help. */
export function helpButton() {
  const dialog = el('dialog', { className: 'modelling-help' },
    el('h2', {}, 'Modelling a plant'),
    TOPICS.map(([title, text]) => el('section', {}, el('h3', {}, title), el('p', {}, text))),
    el('form', { method: 'dialog' }, el('button', { className: 'primary' }, 'Close')));
  document.body.append(dialog);
  return el('button', { type: 'button', 'data-action': 'help', title: 'How to model a plant', onclick: () => dialog.showModal() }, 'Help');
}
