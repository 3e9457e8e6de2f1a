package org.ktcs.kernel.web.v1

import kotlinx.serialization.DeserializationStrategy
import kotlinx.serialization.SerializationException
import kotlinx.serialization.json.Json
import kotlinx.serialization.serializer
import org.ktcs.api.error.InvalidRequestException

/**
 * The JSON format of openTCS's web API v1: every field is written, `null`s included, as openTCS's Jackson setup does;
 * status messages carry their kind in `type`.
 */
object V1Json {
    val json: Json = Json {
        encodeDefaults = true
        explicitNulls = true
        classDiscriminator = "type"
    }

    /** Decodes a request body, turning malformed JSON into an [InvalidRequestException]. */
    inline fun <reified T> decodeRequest(text: String): T = decodeRequest(serializer<T>(), text)

    /** Decodes a request body with [deserializer], turning malformed JSON into an [InvalidRequestException]. */
    fun <T> decodeRequest(deserializer: DeserializationStrategy<T>, text: String): T = try {
        json.decodeFromString(deserializer, text)
    } catch (e: SerializationException) {
        throw InvalidRequestException("Malformed request body: ${e.message}")
    } catch (e: IllegalArgumentException) {
        throw InvalidRequestException("Malformed request body: ${e.message}")
    }
}
