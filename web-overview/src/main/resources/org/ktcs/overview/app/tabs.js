// The side bar's tabs: operation views and the extensions' panels.

import { el } from './dom.js';

export class Tabs {
  constructor(bar, bodies) {
    this.bar = bar;
    this.bodies = bodies;
    this.tabs = new Map();
    this.activationListeners = new Map();
  }

  /** Calls listener each time the tab id is activated. */
  onActivate(id, listener) {
    this.activationListeners.set(id, [...(this.activationListeners.get(id) ?? []), listener]);
  }

  /** Adds a tab and answers its (hidden) body element. */
  add(id, title) {
    const button = el('button', {
      type: 'button', className: 'tab', role: 'tab', 'data-tab': id, onclick: () => this.activate(id),
    }, el('span', {}, title), el('span', { className: 'badge', hidden: true }));
    const body = el('div', { className: 'tab-body', role: 'tabpanel', 'data-tab-body': id, hidden: true });
    this.bar.append(button);
    this.bodies.append(body);
    this.tabs.set(id, { button, body });
    return body;
  }

  activate(id) {
    for (const [tabId, { button, body }] of this.tabs) {
      const active = tabId === id;
      button.classList.toggle('active', active);
      button.setAttribute('aria-selected', String(active));
      body.hidden = !active;
    }
    this.active = id;
    this.setBadge(id, '');
    (this.activationListeners.get(id) ?? []).forEach((listener) => listener());
  }

  setBadge(id, text) {
    const badge = this.tabs.get(id)?.button.querySelector('.badge');
    if (!badge) return;
    badge.textContent = text;
    badge.hidden = !text;
  }
}
