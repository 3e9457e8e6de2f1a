// The header's switch between the operating mode (the running plant, its vehicles and orders) and the modelling
// mode (the plant model being edited). The modelling mode is built on first use.

import { ModellingMode } from './editor.js';

/**
 * @param {{plant: any, ktcs: any, client: any, details: any}} parts
 * @returns {{active: boolean, runningModel: any, mode: ModellingMode|null}}
 */
export function installModellingMode({ plant, ktcs, client, details }) {
  const operating = document.getElementById('mode-operating');
  const modelling = document.getElementById('mode-modelling');
  const state = { active: false, runningModel: null, mode: null };
  const show = (active) => {
    state.active = active;
    document.body.classList.toggle('modelling', active);
    document.getElementById('modelling-toolbar').hidden = !active;
    document.getElementById('modelling-panel').hidden = !active;
    for (const [button, on] of [[operating, !active], [modelling, active]]) {
      button.classList.toggle('active', on);
      button.setAttribute('aria-pressed', String(on));
    }
  };
  modelling.onclick = async () => {
    if (state.active) return;
    details.show(null);
    state.mode ??= new ModellingMode({
      plant, ktcs, client,
      toolbar: document.getElementById('modelling-toolbar'),
      panel: document.getElementById('modelling-panel'),
      onActiveChange: show,
    });
    try {
      await state.mode.enter();
    } catch (error) {
      ktcs.notify(`The modelling mode could not start: ${error.message}`, 'error');
    }
  };
  operating.onclick = () => state.mode?.leave(state.runningModel);
  return state;
}
