package org.ktcs.overview

import io.ktor.http.ContentType
import io.ktor.http.HttpHeaders
import io.ktor.http.HttpStatusCode
import io.ktor.server.application.ApplicationCall
import io.ktor.server.response.header
import io.ktor.server.response.respond
import io.ktor.server.response.respondBytes
import io.ktor.server.response.respondText
import io.ktor.server.routing.Route
import io.ktor.server.routing.get
import io.ktor.server.routing.route
import kotlinx.serialization.Serializable
import kotlinx.serialization.builtins.ListSerializer
import kotlinx.serialization.json.Json
import org.ktcs.api.driver.DriverPanel
import org.ktcs.extension.web.WebContribution

/**
 * The overview's routes: the page at `/`, its own files at `/overview/app/`, the list of panels and themes at
 * `/overview/extensions.json`, their files at `/overview/extensions/{name}/`, the files of each driver's panel at
 * `/overview/drivers/{driver}/`, and what the page must know about
 * the configuration at `/overview/settings.json`. None of this is secret; the web API behind it keeps its access key.
 */
class OverviewRoutes(
    private val contributions: Contributions,
    private val themes: ThemeSelection,
    private val accessKeyRequired: Boolean,
    private val driverPanel: (driver: String) -> DriverPanel? = { null },
) : WebContribution {
    private val json = Json { encodeDefaults = true }
    private val app = ClassPathFiles(OverviewRoutes::class.java.classLoader, APP_DIRECTORY)

    override fun install(root: Route) {
        root.get("/") { call.respondFile(app, "index.html") }
        root.route("/overview") {
            get("/app/{path...}") { call.respondFile(app, call.tail()) }
            get("/extensions.json") {
                val listing = json.encodeToString(
                    ListSerializer(ContributionEntry.serializer()),
                    contributions.listing(),
                )
                call.respondText(listing, ContentType.Application.Json)
            }
            get("/settings.json") {
                val settings = OverviewSettings(themes.vehicleTheme, themes.locationTheme, accessKeyRequired)
                call.respondText(
                    json.encodeToString(OverviewSettings.serializer(), settings),
                    ContentType.Application.Json,
                )
            }
            get("/drivers/{driver}/{path...}") {
                val panel = driverPanel(call.parameters["driver"].orEmpty())
                if (panel == null) {
                    call.respond(HttpStatusCode.NotFound)
                } else {
                    call.respondFile(ClassPathFiles(panel.classLoader, panel.resourceDirectory), call.tail())
                }
            }
            get("/extensions/{name}/{path...}") {
                val contribution = contributions[call.parameters["name"].orEmpty()]
                if (contribution == null) {
                    call.respond(HttpStatusCode.NotFound)
                } else {
                    val files = ClassPathFiles(contribution.classLoader, contribution.resourceDirectory)
                    call.respondFile(files, call.tail())
                }
            }
        }
    }

    private fun ApplicationCall.tail(): String = parameters.getAll("path").orEmpty().joinToString("/")

    private suspend fun ApplicationCall.respondFile(files: ClassPathFiles, path: String) {
        val file = files.read(path)
        if (file == null) {
            respond(HttpStatusCode.NotFound)
        } else {
            // Operators keep the page open for a shift; after an update a reload must fetch the new files.
            response.header(HttpHeaders.CacheControl, "no-cache")
            respondBytes(file.bytes, file.contentType)
        }
    }

    private companion object {
        const val APP_DIRECTORY = "org/ktcs/overview/app"
    }
}

/** What the page needs to know of the configuration. */
@Serializable
data class OverviewSettings(val vehicleTheme: String, val locationTheme: String, val accessKeyRequired: Boolean)
