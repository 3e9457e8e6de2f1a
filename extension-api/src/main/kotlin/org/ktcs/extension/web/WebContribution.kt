package org.ktcs.extension.web

import io.ktor.server.routing.Route

/**
 * Routes an extension adds to the kernel application's web server, next to the web API (the browser overview is
 * one). Bind implementations in the extension's Koin module; each is installed once at the root of the routing tree,
 * outside `/v1` and its access key.
 */
public fun interface WebContribution {
    public fun install(root: Route)
}
