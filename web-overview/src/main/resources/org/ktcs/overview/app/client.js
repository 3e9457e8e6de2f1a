// The page's only way to the kernel: the public web API (REST v1) and its WebSocket, like any other client.

const TOPICS = ['vehicles', 'transportOrders', 'orderSequences', 'plantModel', 'notifications', 'driverEvents'];
// Topics whose objects are a list in arrival order (the latest kept), not a map by name.
const LIST_TOPICS = new Set(['notifications', 'driverEvents']);
// The topics whose events carry only what changed of an object (onlyChanged): the others send whole objects.
const MERGED_TOPICS = new Set(['vehicles', 'transportOrders']);
const RECONNECT_DELAYS_MS = [500, 1000, 2000, 5000];

/** An API error: the message joins the API's error array. */
export class ApiError extends Error {
  constructor(status, messages) {
    super(messages.join('; ') || `HTTP ${status}`);
    this.status = status;
  }
}

/**
 * Keeps one WebSocket to /v1/ws open, subscribed to every topic, and the latest state of each topic. After a lost
 * connection it reconnects by itself; the server then sends fresh snapshots, so listeners resynchronise.
 */
export class KtcsClient {
  constructor({ accessKey = '' } = {}) {
    this.accessKey = accessKey;
    this.listeners = new Map(TOPICS.map((topic) => [topic, new Set()]));
    this.state = new Map();
    this.connectionListeners = new Set();
    this.modelReplacedListeners = new Set();
    this.connected = false;
    this.attempt = 0;
    this.socket = null;
    this.reconnectNotBefore = 0;
  }

  /** Calls REST v1; resolves with the parsed JSON (or null), rejects with an ApiError naming the problem. */
  async api(method, path, body) {
    // The custom header marks the request as a program's, not a form's: kTCS refuses browser requests that change
    // something without it (or a JSON body), so that no other web page can.
    const headers = { 'X-Requested-With': 'kTCS overview' };
    if (body !== undefined) headers['Content-Type'] = 'application/json';
    if (this.accessKey) headers['X-Api-Access-Key'] = this.accessKey;
    let response;
    try {
      response = await fetch(`/v1${path}`, {
        method, headers, body: body === undefined ? undefined : JSON.stringify(body),
      });
    } catch (error) {
      throw new ApiError(0, [`kTCS is not reachable (${error.message})`]);
    }
    const text = await response.text();
    const parsed = text ? parseJson(text) : null;
    if (!response.ok) {
      const messages = Array.isArray(parsed) ? parsed.map(String) : [text || response.statusText];
      throw new ApiError(response.status, messages.map((m) => `${m} (HTTP ${response.status})`));
    }
    return parsed;
  }

  /** Calls listener with each message of topic; a late subscriber first gets the current state as a snapshot. */
  subscribe(topic, listener) {
    const listeners = this.listeners.get(topic);
    if (!listeners) throw new Error(`unknown topic '${topic}'; known: ${TOPICS.join(', ')}`);
    listeners.add(listener);
    if (this.state.has(topic)) {
      listener({ v: 1, type: 'snapshot', topic, objects: this.objects(topic) });
    }
    return () => listeners.delete(listener);
  }

  /** The current objects of a topic, as the last snapshot and the events since made them. */
  objects(topic) {
    const state = this.state.get(topic);
    if (!state) return [];
    return Array.isArray(state) ? [...state] : [...state.values()];
  }

  onConnectionChange(listener) {
    this.connectionListeners.add(listener);
    listener(this.connected);
  }

  /** Calls listener with the new model's name when the plant model is replaced; fresh snapshots follow. */
  onModelReplaced(listener) {
    this.modelReplacedListeners.add(listener);
    return () => this.modelReplacedListeners.delete(listener);
  }

  connect() {
    const scheme = location.protocol === 'https:' ? 'wss' : 'ws';
    const query = this.accessKey ? `?accessKey=${encodeURIComponent(this.accessKey)}` : '';
    const socket = new WebSocket(`${scheme}://${location.host}/v1/ws${query}`);
    this.socket = socket;
    socket.onopen = () => {
      this.attempt = 0;
      // Only a removed object's previous state is used (its name), so the others are not sent at all; nor are a
      // vehicle's or an order's fields that did not change (an order's routes while it advances step by step):
      // applyEvent merges what changed into the object it has.
      socket.send(JSON.stringify({
        type: 'subscribe', topics: TOPICS, previous: false, onlyChanged: true, shortenedLists: true,
      }));
      this.setConnected(true);
    };
    socket.onmessage = (message) => this.receive(parseJson(message.data));
    socket.onclose = () => {
      if (this.socket !== socket) return;
      this.setConnected(false);
      const backOff = RECONNECT_DELAYS_MS[Math.min(this.attempt, RECONNECT_DELAYS_MS.length - 1)];
      const delay = Math.max(backOff, this.reconnectNotBefore - Date.now());
      this.attempt += 1;
      setTimeout(() => this.connect(), delay);
    };
  }

  /** Closes the socket as a network failure would; reconnects by itself, not before offlineMs have passed. */
  dropConnection(offlineMs = 0) {
    this.reconnectNotBefore = Date.now() + offlineMs;
    this.socket?.close();
  }

  setConnected(connected) {
    this.connected = connected;
    this.connectionListeners.forEach((listener) => listener(connected));
  }

  receive(message) {
    if (!message || !message.type) return;
    if (message.type === 'snapshot') this.applySnapshot(message);
    else if (message.type === 'event') this.applyEvent(message);
    else if (message.type === 'error') console.warn(`kTCS WebSocket: ${message.message}`);
    else if (message.type === 'modelReplaced') this.notifyAll(this.modelReplacedListeners, message.name);
    // "missed" needs nothing here: fresh snapshots of every topic follow it.
    const listeners = this.listeners.get(message.topic);
    if (listeners) this.notifyAll(listeners, message);
  }

  notifyAll(listeners, argument) {
    for (const listener of listeners) {
      try {
        listener(argument);
      } catch (error) {
        reportListenerError(error);
      }
    }
  }

  applySnapshot({ topic, objects }) {
    if (LIST_TOPICS.has(topic)) this.state.set(topic, [...objects]);
    else this.state.set(topic, new Map(objects.map((object) => [object.name, object])));
  }

  applyEvent(message) {
    const { topic, previous, unchanged, shortened } = message;
    const state = this.state.get(topic);
    if (!state) return;
    // A vehicle's or an order's event has only what changed: it is merged into the object's state before, the
    // fields left out as unchanged are put back from it and the lists left out as shortened are cut from it, so
    // listeners see whole objects.
    const before = message.current && MERGED_TOPICS.has(topic) ? state.get(message.current.name) : undefined;
    if (before) {
      message.current = { ...before, ...message.current };
      for (const field of unchanged ?? []) message.current[field] = before[field];
      for (const [field, dropped] of Object.entries(shortened ?? {})) {
        message.current[field] = before[field].slice(dropped);
      }
    }
    const { current } = message;
    if (LIST_TOPICS.has(topic)) {
      state.push(current);
      if (state.length > 1000) state.shift();
    } else if (topic === 'plantModel') {
      applyPlantModelChange(state, current);
    } else if (current === null) {
      state.delete(previous.name);
    } else {
      state.set(current.name, current);
    }
  }
}

// Path and location events change the single plant model object in place, so model() stays current.
function applyPlantModelChange(state, changed) {
  const model = [...state.values()][0];
  if (!model || !changed) return;
  for (const list of [model.paths, model.locations]) {
    const index = list.findIndex((element) => element.name === changed.name);
    if (index >= 0 && isSameKind(list[index], changed)) {
      list[index] = changed;
      return;
    }
  }
}

function isSameKind(a, b) {
  return ('srcPointName' in a) === ('srcPointName' in b);
}

function parseJson(text) {
  try {
    return JSON.parse(text);
  } catch {
    return null;
  }
}

function reportListenerError(error) {
  // A broken panel must not stop the overview; the page's error handler shows it to the operator.
  setTimeout(() => { throw error; });
}
