package org.ktcs.kernel.persistence

import org.ktcs.api.model.PlantModel
import org.ktcs.kernel.persistence.v002.V002PlantModelTO
import org.ktcs.kernel.persistence.v002.toDomain
import org.ktcs.kernel.persistence.v004.V004PlantModelTO
import org.ktcs.kernel.persistence.v004.toDomain
import org.ktcs.kernel.persistence.v7.V7PlantModelTO
import org.ktcs.kernel.persistence.v7.toDomain

/** Which transfer objects read which schema version. */
internal object PlantModelVersions {
    private val readers: Map<String, (ByteArray, ReadWarnings, String) -> PlantModel> = mapOf(
        "0.0.2" to
            { bytes, warnings, source -> decode<V002PlantModelTO>(bytes, warnings, source).toDomain(source, warnings) },
        "0.0.3" to
            { bytes, warnings, source -> decode<V002PlantModelTO>(bytes, warnings, source).toDomain(source, warnings) },
        "0.0.4" to { bytes, warnings, source -> decode<V004PlantModelTO>(bytes, warnings, source).toDomain(warnings) },
        "0.0.5" to { bytes, warnings, source -> decode<V004PlantModelTO>(bytes, warnings, source).toDomain(warnings) },
        "6.0.0" to { bytes, warnings, source -> decode<V7PlantModelTO>(bytes, warnings, source).toDomain() },
        "7.0.0" to { bytes, warnings, source -> decode<V7PlantModelTO>(bytes, warnings, source).toDomain() },
    )

    val supported: List<String> = readers.keys.toList()

    fun read(bytes: ByteArray, source: String): ModelRead {
        val header = peekHeader(bytes, source)
        val reader = readers[header.version] ?: throw ModelFileException(
            "${header.where}: unsupported plant model version \"${header.version}\" (${supportedVersionsText()})",
        )
        val warnings = ReadWarnings(source)
        val model = reader(SplitElements.regroup(bytes, source, warnings), warnings, source)
        return ModelRead(model, warnings.all())
    }

    // Files the streaming reader cannot read completely, Jackson reads: with its warnings and error messages.
    private inline fun <reified T : Any> decode(bytes: ByteArray, warnings: ReadWarnings, source: String): T =
        StreamingModelReader.read(bytes, T::class.java) ?: decodeWithJackson(bytes, warnings, source)

    private inline fun <reified T> decodeWithJackson(bytes: ByteArray, warnings: ReadWarnings, source: String): T =
        decoding(source) { ModelXml.mapper.readerFor(T::class.java).withHandler(warnings.handler).readValue(bytes) }
}
