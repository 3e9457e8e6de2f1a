// The kernel's model-file services (POST /v1/plantModel/fromFile, /toFile, /validation) and publishing
// (PUT /v1/plantModel): the page leaves openTCS's file format and the validation rules to the kernel.

/** @typedef {{severity: 'ERROR'|'WARNING', element: string, name: string|null, message: string}} ModelProblem */

export class KernelFiles {
  /** @param {string} accessKey the web API's access key, if kTCS requires one */
  constructor(accessKey = '') {
    this.accessKey = accessKey;
  }

  /** The model of an openTCS file (any supported version) and the reader's warnings. */
  async read(fileText) {
    const response = await this.raw('POST', '/v1/plantModel/fromFile', fileText, 'application/xml');
    return response.json();
  }

  /** The openTCS 7.0.0 file of [model], as openTCS writes it. */
  async write(model) {
    const response = await this.raw('POST', '/v1/plantModel/toFile', JSON.stringify(model), 'application/json');
    return response.text();
  }

  /** @returns {Promise<{valid: boolean, problems: ModelProblem[]}>} */
  async validate(model) {
    const response = await this.raw('POST', '/v1/plantModel/validation', JSON.stringify(model), 'application/json');
    return response.json();
  }

  /** Replaces the kernel's plant with [model]; throws with kTCS's reason (e.g. orders under way) if refused. */
  async publish(model) {
    await this.raw('PUT', '/v1/plantModel', JSON.stringify(model), 'application/json');
  }

  async raw(method, path, body, contentType) {
    // The custom header marks the request as the overview's (kTCS refuses cross-site requests that change things).
    const headers = { 'Content-Type': contentType, 'X-Requested-With': 'kTCS overview' };
    if (this.accessKey) headers['X-Api-Access-Key'] = this.accessKey;
    const response = await fetch(path, { method, headers, body });
    if (!response.ok) {
      const text = await response.text();
      let reason = text;
      try {
        reason = JSON.parse(text).join('; ');
      } catch { /* not kTCS's error array */ }
      throw Object.assign(new Error(reason || `HTTP ${response.status}`), { status: response.status });
    }
    return response;
  }
}
