package org.ktcs.kernel.web.v1

import kotlinx.serialization.KSerializer
import kotlinx.serialization.SerializationException
import kotlinx.serialization.descriptors.PrimitiveKind
import kotlinx.serialization.descriptors.PrimitiveSerialDescriptor
import kotlinx.serialization.descriptors.SerialDescriptor
import kotlinx.serialization.encoding.Decoder
import kotlinx.serialization.encoding.Encoder
import kotlinx.serialization.json.JsonDecoder
import kotlinx.serialization.json.JsonEncoder
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.jsonPrimitive

/** A double that is written as the string `"NaN"` when unknown, as Jackson does for openTCS's orientation angles. */
object NanAsStringSerializer : KSerializer<Double> {
    override val descriptor: SerialDescriptor =
        PrimitiveSerialDescriptor("org.ktcs.NanAsStringDouble", PrimitiveKind.DOUBLE)

    override fun serialize(encoder: Encoder, value: Double) {
        if (value.isNaN() && encoder is JsonEncoder) {
            encoder.encodeJsonElement(JsonPrimitive("NaN"))
        } else {
            encoder.encodeDouble(value)
        }
    }

    override fun deserialize(decoder: Decoder): Double {
        if (decoder !is JsonDecoder) return decoder.decodeDouble()
        val content = decoder.decodeJsonElement().jsonPrimitive.content
        return content.toDoubleOrNull() ?: throw SerializationException("'$content' is not a number")
    }
}
