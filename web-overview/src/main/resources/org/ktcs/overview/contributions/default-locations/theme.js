// kTCS's default location theme: the symbol follows the location's representation (or else its type's), as the
// openTCS plant overview draws them.

/** @type {Array<[RegExp, { fill: string, stroke: string, symbol: string }]>} */
const BY_REPRESENTATION = [
  [/^LOAD_TRANSFER/, { fill: '#b3e5fc', stroke: '#01579b', symbol: 'square' }],
  [/^RECHARGE/, { fill: '#fff59d', stroke: '#f57f17', symbol: 'triangle' }],
  [/^WORKING/, { fill: '#c5e1a5', stroke: '#33691e', symbol: 'diamond' }],
  [/^NONE$/, { fill: '#eeeeee', stroke: '#616161', symbol: 'circle' }],
];
const OTHER = { fill: '#e1bee7', stroke: '#4a148c', symbol: 'square' };

export default {
  locationStyle(location, locationType) {
    const own = location.layout?.locationRepresentation;
    const representation = own && own !== 'DEFAULT' ? own : locationType?.layout?.locationRepresentation ?? 'NONE';
    const found = BY_REPRESENTATION.find(([pattern]) => pattern.test(representation));
    return { ...(found ? found[1] : OTHER) };
  },
};
