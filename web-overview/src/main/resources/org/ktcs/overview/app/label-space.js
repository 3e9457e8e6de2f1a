// Keeps the plant's names from being written over each other: a name goes where no name drawn before it in this
// frame is, or is left out (the element's details still name it). A grid of screen cells keeps each check local.

const CELL = 64;

export class LabelSpace {
  constructor() {
    this.cells = new Map();
    this.boxes = [];
  }

  /** Records the box and answers true if it covers no box placed before; answers false and records nothing if it does. */
  tryPlace(box) {
    const keys = cellKeys(box);
    for (const key of keys) {
      if (this.cells.get(key)?.some((other) => overlaps(box, other))) return false;
    }
    for (const key of keys) {
      if (!this.cells.has(key)) this.cells.set(key, []);
      this.cells.get(key).push(box);
    }
    this.boxes.push(box);
    return true;
  }
}

/** The box of a text centred at x with its top at y. */
export function textBox(ctx, text, x, y, height) {
  const width = ctx.measureText(text).width + 4;
  return { minX: x - width / 2, maxX: x + width / 2, minY: y, maxY: y + height };
}

function overlaps(a, b) {
  return a.minX < b.maxX && b.minX < a.maxX && a.minY < b.maxY && b.minY < a.maxY;
}

function cellKeys(box) {
  const keys = [];
  for (let cx = Math.floor(box.minX / CELL); cx <= Math.floor(box.maxX / CELL); cx += 1) {
    for (let cy = Math.floor(box.minY / CELL); cy <= Math.floor(box.maxY / CELL); cy += 1) keys.push(`${cx},${cy}`);
  }
  return keys;
}
