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
    private val readers: Map<String, (ByteArray, String) -> PlantModel> = mapOf(
        "0.0.2" to { bytes, source -> decode<V002PlantModelTO>(bytes, source).toDomain(source) },
        "0.0.3" to { bytes, source -> decode<V002PlantModelTO>(bytes, source).toDomain(source) },
        "0.0.4" to { bytes, source -> decode<V004PlantModelTO>(bytes, source).toDomain() },
        "0.0.5" to { bytes, source -> decode<V004PlantModelTO>(bytes, source).toDomain() },
        "6.0.0" to { bytes, source -> decode<V7PlantModelTO>(bytes, source).toDomain() },
        "7.0.0" to { bytes, source -> decode<V7PlantModelTO>(bytes, source).toDomain() },
    )

    val supported: List<String> = readers.keys.toList()

    fun read(bytes: ByteArray, source: String): PlantModel {
        val header = peekHeader(bytes, source)
        val reader = readers[header.version] ?: throw ModelFileException(
            "${header.where}: unsupported plant model version \"${header.version}\" (${supportedVersionsText()})",
        )
        return reader(bytes, source)
    }

    private inline fun <reified T> decode(bytes: ByteArray, source: String): T =
        decoding(source) { ModelXml.mapper.readValue(bytes, T::class.java) }
}
