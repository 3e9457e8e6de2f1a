/** Calls fn at most once per interval (and once more after the last call), so a burst of events renders once. */
export function throttle(fn, intervalMs) {
  let timer = null;
  let pending = false;
  return () => {
    if (timer) {
      pending = true;
      return;
    }
    fn();
    timer = setTimeout(function again() {
      timer = null;
      if (pending) {
        pending = false;
        fn();
        timer = setTimeout(again, intervalMs);
      }
    }, intervalMs);
  };
}
