// Every operator action goes through here, so its result (or the API's error message) is always shown.

/** Runs an API action; shows "label: done" or "label failed: <API message>". */
export async function act(ktcs, label, action) {
  try {
    const result = await action();
    ktcs.notify(`${label}: done`, 'info');
    return result;
  } catch (error) {
    ktcs.notify(`${label} failed: ${error.message}`, 'error');
    return undefined;
  }
}

export const enc = encodeURIComponent;
