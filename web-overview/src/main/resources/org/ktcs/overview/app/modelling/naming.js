// New elements' names as openTCS's Model Editor gives them: a prefix and the next free four-digit number
// ("Point-0001", "Location-0002", "LType-0001", "Vehicle-0001", "Block-0001"); a path is named after its ends.

/** The prefix followed by one more than the highest number any name with that prefix has, four digits at least. */
export function nextName(prefix, elements) {
  let highest = 0;
  for (const { name } of elements) {
    if (!name.startsWith(prefix)) continue;
    const number = Number(name.slice(prefix.length));
    if (Number.isInteger(number) && number > highest) highest = number;
  }
  return `${prefix}${String(highest + 1).padStart(4, '0')}`;
}

/** A path's name: its source and destination point names, as openTCS names paths. */
export function pathName(src, dst) {
  return `${src} --- ${dst}`;
}
