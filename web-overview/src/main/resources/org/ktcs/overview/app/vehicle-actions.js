// What an operator can do with a vehicle, each through the web API with its result shown.

import { el } from './dom.js';
import { act, enc } from './actions.js';

const INTEGRATION_LEVELS = ['TO_BE_IGNORED', 'TO_BE_NOTICED', 'TO_BE_RESPECTED', 'TO_BE_UTILIZED'];

export function vehicleActions(ktcs, name, currentLevel) {
  const path = `/vehicles/${enc(name)}`;
  const run = (label, method, suffix, body) => act(ktcs, `${label} (${name})`, () => ktcs.api(method, `${path}${suffix}`, body));
  const level = el('select', { 'aria-label': 'Integration level' },
    INTEGRATION_LEVELS.map((value) => el('option', { value, selected: value === currentLevel }, value)));
  const messageType = el('input', { placeholder: 'message type, e.g. tcs:virtualVehicle:setState', size: 28 });
  const messageParameters = el('input', { placeholder: 'key=value, key=value', size: 28 });
  const sendMessage = () => {
    const parameters = messageParameters.value.split(',').map((pair) => pair.trim()).filter(Boolean).map((pair) => {
      const [key, ...value] = pair.split('=');
      return { key: key.trim(), value: value.join('=').trim() };
    });
    return run('Driver message', 'POST', '/commAdapter/message', { type: messageType.value.trim(), parameters });
  };
  return [
    el('div', { className: 'action-row' }, level,
      el('button', { type: 'button', onclick: () => run(`Integration level ${level.value}`, 'PUT', `/integrationLevel?newValue=${level.value}`) }, 'Set level')),
    el('div', { className: 'action-row' },
      el('button', { type: 'button', onclick: () => run('Pause', 'PUT', '/paused?newValue=true') }, 'Pause'),
      el('button', { type: 'button', onclick: () => run('Resume', 'PUT', '/paused?newValue=false') }, 'Resume'),
      el('button', { type: 'button', onclick: () => run('Withdraw order', 'POST', '/withdrawal?immediate=false') }, 'Withdraw order'),
      el('button', { type: 'button', className: 'danger', onclick: () => run('Withdraw order immediately', 'POST', '/withdrawal?immediate=true') }, 'Withdraw immediately')),
    el('div', { className: 'action-row' },
      el('button', { type: 'button', onclick: () => run('Enable driver', 'PUT', '/commAdapter/enabled?newValue=true') }, 'Enable driver'),
      el('button', { type: 'button', onclick: () => run('Disable driver', 'PUT', '/commAdapter/enabled?newValue=false') }, 'Disable driver')),
    el('div', { className: 'action-row' }, messageType, messageParameters,
      el('button', { type: 'button', onclick: sendMessage }, 'Send message')),
  ];
}
