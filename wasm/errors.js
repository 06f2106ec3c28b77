// MeshError: the one error type the package throws for bad input or a failed mesh.
//
// `code` is stable and meant for branching. The codes are ruppert::ErrorCode's names
// (kErrorCodeNames in core/include/ruppert/ruppert.h, as the binding exports them into
// dist/names.js); values of the wrong JavaScript type are MALFORMED_INPUT.
import { NAMES } from './dist/names.js';

/** Every code a MeshError can carry: ruppert::ErrorCode's names, in enum order (from the binding). */
export const ERROR_CODES = NAMES.errorCodes;

export class MeshError extends Error {
  /**
   * @param {string} code one of ERROR_CODES
   * @param {string} message names the offending item, e.g. "segments[7] = 2.5 is not an integer"
   * @param {{ cause?: unknown }} [options]
   */
  constructor(code, message, options) {
    super(message, options);
    this.name = 'MeshError';
    this.code = code;
  }
}
