package org.ktcs.kernel.web.docs

import io.ktor.http.ContentType
import io.ktor.http.defaultForFileExtension
import java.util.Properties

/** Where the swagger-ui webjar keeps its files; the folder is named after the webjar's version. */
internal object SwaggerUiWebjar {
    private const val POM_PROPERTIES = "/META-INF/maven/org.webjars/swagger-ui/pom.properties"

    val version: String by lazy {
        val properties = Properties()
        val stream = requireNotNull(javaClass.getResourceAsStream(POM_PROPERTIES)) {
            "the swagger-ui webjar is not on the class path ($POM_PROPERTIES is missing)"
        }
        stream.use(properties::load)
        requireNotNull(properties.getProperty("version")) { "$POM_PROPERTIES names no version" }
    }

    /** One file of Swagger UI's distribution (`swagger-ui-bundle.js`, ...), or `null` if the webjar has none. */
    fun asset(name: String): Asset? {
        if (!ASSET_NAME.matches(name)) return null
        val resource = javaClass.getResource("/META-INF/resources/webjars/swagger-ui/$version/$name") ?: return null
        return Asset(resource.readBytes(), ContentType.defaultForFileExtension(name.substringAfterLast('.')))
    }

    class Asset(val bytes: ByteArray, val contentType: ContentType)

    // Plain file names only: no way out of the webjar's folder.
    private val ASSET_NAME = Regex("[A-Za-z0-9._-]+\\.(js|css|png|html|map)")
}
