// Undo/redo by snapshots: every committed edit pushes a copy of the drawing. Drawings are small
// (a few thousand numbers), so whole copies are simpler and safer than inverse operations.
import { cloneDrawing } from '../model/drawing.js';

const LIMIT = 200;

const sameDrawing = (a, b) => JSON.stringify(a) === JSON.stringify(b);

export class History {
  /** @param {object} initial the drawing to start from */
  constructor(initial) {
    this.undoStack = [];
    this.redoStack = [];
    this.current = cloneDrawing(initial);
  }

  /** Records `next` as the new state (after an edit); false when nothing changed. */
  commit(next) {
    // Several events may report one edit (a slider's input and change): keep one undo step.
    if (sameDrawing(next, this.current)) return false;
    this.undoStack.push(this.current);
    if (this.undoStack.length > LIMIT) this.undoStack.shift();
    this.redoStack = [];
    this.current = cloneDrawing(next);
    return true;
  }

  /** Replaces the state without an undo entry (loading a link on startup). */
  reset(next) {
    this.undoStack = [];
    this.redoStack = [];
    this.current = cloneDrawing(next);
  }

  get canUndo() { return this.undoStack.length > 0; }
  get canRedo() { return this.redoStack.length > 0; }

  /** Returns a copy of the restored drawing, or null when there is nothing to undo. */
  undo() {
    if (!this.canUndo) return null;
    this.redoStack.push(this.current);
    this.current = this.undoStack.pop();
    return cloneDrawing(this.current);
  }

  redo() {
    if (!this.canRedo) return null;
    this.undoStack.push(this.current);
    this.current = this.redoStack.pop();
    return cloneDrawing(this.current);
  }
}
