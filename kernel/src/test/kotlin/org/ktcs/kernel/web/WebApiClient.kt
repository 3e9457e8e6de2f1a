package org.ktcs.kernel.web

import org.ktcs.kernel.web.contract.WebApiContracts
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse

/**
 * The HTTP client of the web API tests. Every response is checked against kTCS's OpenAPI document and openTCS's v1
 * specification ([WebApiContracts]) before the test sees it, so any test that calls the API is a contract test too.
 */
class WebApiClient(val http: HttpClient = HttpClient.newHttpClient()) {
    fun call(method: String, url: String, body: String? = null, key: String? = null): HttpResponse<String> {
        val publisher = body?.let(HttpRequest.BodyPublishers::ofString) ?: HttpRequest.BodyPublishers.noBody()
        val request = HttpRequest.newBuilder(URI(url)).method(method, publisher)
        key?.let { request.header("X-Api-Access-Key", it) }
        if (body != null) request.header("Content-Type", "application/json")
        val response = http.send(request.build(), HttpResponse.BodyHandlers.ofString())
        // A CORS preflight is answered by the CORS plugin for any path; it is no operation of the API.
        if (method != "OPTIONS") {
            WebApiContracts.check(
                method,
                url,
                response.statusCode(),
                response.headers().firstValue("Content-Type").orElse(null),
                response.body(),
            )
        }
        return response
    }
}
