// A location theme for bright halls and weak eyes: black and yellow, with a letter for what happens there.

export default {
  locationStyle(location, locationType) {
    const operations = (locationType?.allowedOperations ?? []).join(' ').toLowerCase();
    let symbol = 'square';
    if (operations.includes('charge')) symbol = 'C';
    else if (operations.includes('load')) symbol = 'L';
    else if (operations.includes('park')) symbol = 'P';
    return { fill: location.locked ? '#ff0000' : '#ffff00', stroke: '#000000', symbol, lineWidth: 3 };
  },
};
