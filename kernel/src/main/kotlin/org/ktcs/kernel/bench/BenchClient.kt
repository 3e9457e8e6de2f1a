package org.ktcs.kernel.bench

import kotlinx.serialization.json.Json
import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.jsonArray
import kotlinx.serialization.json.jsonObject
import kotlinx.serialization.json.jsonPrimitive
import java.net.URI
import java.net.URLEncoder
import java.net.http.HttpClient
import java.net.http.HttpRequest
import java.net.http.HttpResponse
import java.time.Duration

/** A client of kTCS's web API v1, as any external client would use it; [baseUrl] ends in `/v1`. */
class BenchClient(val baseUrl: String) {
    private val http: HttpClient = HttpClient.newBuilder()
        .version(HttpClient.Version.HTTP_1_1)
        .connectTimeout(Duration.ofSeconds(5))
        .build()

    /** Creates the order `Load cargo` at [from], `Unload cargo` at [to]; returns the status code. */
    fun postOrder(name: String, from: String, to: String): Int {
        val request = HttpRequest.newBuilder(uri(orderPath(name)))
            .header("Content-Type", "application/json")
            .timeout(TIMEOUT)
            .POST(HttpRequest.BodyPublishers.ofString(orderBody(from, to)))
            .build()
        val response = http.send(request, HttpResponse.BodyHandlers.discarding())
        check(response.statusCode() == 200) { "POST order $name answered ${response.statusCode()}" }
        return response.statusCode()
    }

    /** `GET` of [path] under `/v1`: the body, or `null` on any status but 200. */
    fun get(path: String): String? = runCatching {
        val request = HttpRequest.newBuilder(uri(path)).timeout(TIMEOUT).GET().build()
        http.send(request, HttpResponse.BodyHandlers.ofString()).takeIf { it.statusCode() == 200 }?.body()
    }.getOrNull()

    /** `GET` of [path], reading and dropping the body; returns its length in bytes. */
    fun getDiscarding(path: String): Long {
        val request = HttpRequest.newBuilder(uri(path)).timeout(TIMEOUT).GET().build()
        val response = http.send(request, HttpResponse.BodyHandlers.ofInputStream())
        check(response.statusCode() == 200) { "GET $path answered ${response.statusCode()}" }
        // Read into one reused buffer: collecting a list of several megabytes into an array (and that into another)
        // made the bench's own small heap collect fully on every request, and the list's latency was the bench's.
        return response.body().use { body ->
            val discarded = ByteArray(DISCARD_BUFFER_BYTES)
            var length = 0L
            while (true) {
                val read = body.read(discarded)
                if (read < 0) break
                length += read
            }
            length
        }
    }

    /** The state of the transport order [name], or `null` if it is unknown or kTCS does not answer. */
    fun orderState(name: String): String? =
        get(orderPath(name))?.let { Json.parseToJsonElement(it).jsonObject.string("state") }

    /** The vehicles as `GET /vehicles` lists them, or `null` while the web API does not answer. */
    fun vehicles(): List<JsonObject>? = get("/vehicles")?.let { text ->
        Json.parseToJsonElement(text).jsonArray.map { it.jsonObject }
    }

    /** The WebSocket address of kTCS's `/v1/ws`. */
    fun webSocketUri(): URI = URI.create(baseUrl.replaceFirst("http", "ws") + "/ws")

    fun httpClient(): HttpClient = http

    private fun uri(path: String): URI = URI.create(baseUrl + path)

    companion object {
        const val LOAD = "Load cargo"
        const val UNLOAD = "Unload cargo"
        private val TIMEOUT: Duration = Duration.ofSeconds(30)
        private const val DISCARD_BUFFER_BYTES = 64 * 1024

        /** The path under `/v1` of the transport order [name]. */
        fun orderPath(name: String): String = "/transportOrders/${encode(name)}"

        /** The body of a `POST` creating an order that loads cargo at [from] and unloads it at [to]. */
        fun orderBody(from: String, to: String): String =
            """{"destinations":[{"locationName":${quoted(from)},"operation":"$LOAD"},""" +
                """{"locationName":${quoted(to)},"operation":"$UNLOAD"}]}"""

        fun encode(name: String): String = URLEncoder.encode(name, Charsets.UTF_8).replace("+", "%20")

        private fun quoted(text: String): String = JsonPrimitive(text).toString()
    }
}

/** The string value of [key], `null` if it is missing or JSON `null`. */
fun JsonObject.string(key: String): String? = (this[key] as? JsonPrimitive)
    ?.takeIf { it.isString }?.content

/** The array of [key], empty if it is missing. */
fun JsonObject.array(key: String): JsonArray = this[key] as? JsonArray ?: JsonArray(emptyList())

/** The content of the primitive [key]. */
fun JsonObject.primitive(key: String): String? = this[key]?.jsonPrimitive?.content
