// Mounts every panel of every extension (extensions.json) into its own tab. Panels are mounted at start and stay
// mounted while hidden, so a load generator keeps running and statistics keep counting.

import { el, fill } from './dom.js';

export async function mountPanels(extensions, tabs, ktcs, notify) {
  const panels = extensions.filter((entry) => entry.kind === 'panel');
  await Promise.all(panels.map(async (panel) => {
    const body = tabs.add(`panel-${panel.name}`, panel.title);
    const container = el('div', { className: 'panel', 'data-panel': panel.name });
    fill(body, container);
    try {
      const module = (await import(panel.module)).default;
      if (!module || typeof module.mount !== 'function') {
        throw new Error(`its module ${panel.module} has no default export with mount(container, ktcs)`);
      }
      await module.mount(container, ktcs);
    } catch (error) {
      fill(container, el('p', { className: 'form-error' }, `The panel '${panel.title}' could not be loaded: ${error.message}`));
      notify(`Panel '${panel.title}' could not be loaded: ${error.message}`, 'error');
    }
  }));
}
