// What the modelling mode draws over the model: the selection, the validator's errors (red) and warnings (amber)
// on the elements they concern, and the gesture under way (box, path being drawn).

const SELECTION = '#ff9800';
const ERROR = '#d0342c';
const WARNING = '#e0a800';
const MAX_MARKED = 2000;

export class EditOverlay {
  /** @param {import('./editor.js').ModellingMode} editor */
  constructor(editor) {
    this.editor = editor;
    /** What the last frame marked, by element name (for the browser tests). */
    this.marked = new Map();
  }

  draw(ctx) {
    const { plant } = this.editor;
    this.marked.clear();
    if (!plant.geometry) return;
    this.drawProblems(ctx);
    this.drawSelection(ctx);
    this.editor.pointer.draw(ctx);
  }

  drawProblems(ctx) {
    const editor = this.editor;
    if (editor.problemsFor !== editor.draft.model) return;
    let count = 0;
    for (const problem of editor.problems) {
      if (!problem.name || count >= MAX_MARKED) continue;
      const colour = problem.severity === 'ERROR' ? ERROR : WARNING;
      if (this.marked.get(problem.name) === 'ERROR') continue;
      if (this.mark(ctx, problem.name, colour, 11)) {
        this.marked.set(problem.name, problem.severity);
        count += 1;
      }
    }
  }

  drawSelection(ctx) {
    for (const key of this.editor.selection) {
      const name = key.slice(key.indexOf(':') + 1);
      this.mark(ctx, name, SELECTION, 14, key.slice(0, key.indexOf(':')));
    }
  }

  /** Rings a point or location, or traces a path, in [colour]; answers whether the element is drawn. */
  mark(ctx, name, colour, radius, kind = null) {
    const plant = this.editor.plant;
    const geometry = plant.geometry;
    const element = (kind ? plant.elementNamed(kind, name) : null)
      ?? geometry.points.get(name) ?? geometry.locationsByName.get(name) ?? geometry.pathsByName.get(name);
    if (!element) return false;
    ctx.save();
    ctx.strokeStyle = colour;
    ctx.lineWidth = 3;
    ctx.beginPath();
    if (element.kind === 'path') {
      plant.tracePath(ctx, element);
    } else {
      const p = plant.view.toScreen(element.x, element.y);
      ctx.arc(p.x, p.y, radius, 0, 2 * Math.PI);
    }
    ctx.stroke();
    ctx.restore();
    return true;
  }
}
