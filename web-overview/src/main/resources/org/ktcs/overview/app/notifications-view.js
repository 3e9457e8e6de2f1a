// User notifications from the kernel, newest first, as they arrive.

import { el, fill, formatTime } from './dom.js';
import { throttle } from './throttle.js';

const SHOWN = 300;

export class NotificationsView {
  constructor(container, { client, tabs }) {
    this.client = client;
    this.list = el('ol', { className: 'notifications', 'data-view': 'notifications' });
    fill(container, this.list);
    let unseen = 0;
    tabs.onActivate('notifications', () => { unseen = 0; });
    const render = throttle(() => this.render(), 250);
    client.subscribe('notifications', (message) => {
      if (message.type === 'event' && tabs.active !== 'notifications') {
        unseen += 1;
        tabs.setBadge('notifications', String(unseen));
      }
      render();
    });
  }

  render() {
    const notifications = this.client.objects('notifications').slice(-SHOWN).reverse();
    if (notifications.length === 0) {
      fill(this.list, el('li', { className: 'empty' }, 'No notifications.'));
      return;
    }
    fill(this.list, notifications.map((n) => el('li', { className: `level-${n.level}` },
      el('div', { className: 'meta' }, `${formatTime(n.timestamp)} · ${n.level}${n.source ? ` · ${n.source}` : ''}`),
      el('div', {}, n.text))));
  }
}
