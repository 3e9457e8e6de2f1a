package org.ktcs.examples.tcpdriver

import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.jsonObject
import java.net.URI
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse

/** The web API of an in-process kernel, as a client sees it. */
class KernelHttp(private val base: String) {
    private val http = HttpClient.newHttpClient()

    fun get(path: String): JsonObject = Json.parseToJsonElement(send("GET", path, null)).jsonObject

    fun post(path: String, json: String) {
        send("POST", path, json)
    }

    private fun send(method: String, path: String, json: String?): String {
        val body = json?.let { HttpRequest.BodyPublishers.ofString(it) } ?: HttpRequest.BodyPublishers.noBody()
        val request = HttpRequest.newBuilder(URI("$base/v1$path")).method(method, body)
            .header("Content-Type", "application/json").build()
        val response = http.send(request, HttpResponse.BodyHandlers.ofString())
        check(response.statusCode() == 200) { "$method $path: ${response.statusCode()} ${response.body()}" }
        return response.body()
    }
}
