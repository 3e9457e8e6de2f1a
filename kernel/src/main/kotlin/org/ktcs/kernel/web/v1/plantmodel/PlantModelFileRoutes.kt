package org.ktcs.kernel.web.v1.plantmodel

import io.ktor.http.ContentType
import io.ktor.server.request.receiveChannel
import io.ktor.server.response.respond
import io.ktor.server.response.respondText
import io.ktor.server.routing.Route
import io.ktor.server.routing.post
import io.ktor.utils.io.toByteArray
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.withContext
import kotlinx.serialization.Serializable
import org.ktcs.api.error.InvalidRequestException
import org.ktcs.kernel.persistence.ModelFileException
import org.ktcs.kernel.persistence.PlantModelFiles
import org.ktcs.kernel.validation.ModelProblem
import org.ktcs.kernel.validation.PlantModelValidator
import org.ktcs.kernel.web.v1.receiveJson

/**
 * A problem the validator or the file reader found, attached to the element it concerns: [element] as the validator
 * names it (e.g. `path 'A --- B'`), [name] the element's own name where it has one (for a client to find it).
 */
@Serializable
data class ModelProblemDto(val severity: String, val element: String, val name: String?, val message: String)

/** The answer of `POST /plantModel/fromFile`: the file's model and what the reader skipped or changed. */
@Serializable
data class ModelFromFileDto(val model: PlantModelDto, val warnings: List<ModelProblemDto>)

/** The answer of `POST /plantModel/validation`: every error and warning of the model. */
@Serializable
data class ModelValidationDto(val valid: Boolean, val problems: List<ModelProblemDto>)

private val NAMED_ELEMENT = Regex("""^[\w ]+ '(.*)'$""")

private fun ModelProblem.toDto() =
    ModelProblemDto(severity.name, element, NAMED_ELEMENT.find(element)?.groupValues?.get(1), message)

/**
 * The kernel's model-file reader, writer and validator for clients that edit a model (the overview's modelling
 * mode): they work on the model's JSON and leave openTCS's file format and the validation rules to the kernel.
 * Reading, writing and validating a large plant takes a while: it runs on the default dispatcher, not on the web
 * server's event loop, whose other connections would wait meanwhile.
 */
fun Route.plantModelFileRoutes() {
    post("/plantModel/fromFile") {
        val bytes = call.receiveChannel().toByteArray()
        if (bytes.isEmpty()) throw InvalidRequestException("the body is empty; send an openTCS plant-model file")
        val read = try {
            withContext(Dispatchers.Default) { PlantModelFiles.readWithWarnings(bytes.inputStream(), "uploaded file") }
        } catch (error: ModelFileException) {
            throw InvalidRequestException(error.message ?: "not a readable plant-model file")
        }
        call.respond(ModelFromFileDto(read.model.toDto(), read.warnings.map { it.toDto() }))
    }
    post("/plantModel/toFile") {
        val model = call.receiveJson<PlantModelDto>()
        val file = withContext(Dispatchers.Default) { PlantModelFiles.writeToString(model.toCheckedDomain()) }
        call.respondText(file, ContentType.Application.Xml)
    }
    post("/plantModel/validation") {
        val model = call.receiveJson<PlantModelDto>()
        val problems = withContext(Dispatchers.Default) { PlantModelValidator.validate(model.toCheckedDomain()) }
        call.respond(ModelValidationDto(problems.none { it.isError }, problems.map { it.toDto() }))
    }
}
