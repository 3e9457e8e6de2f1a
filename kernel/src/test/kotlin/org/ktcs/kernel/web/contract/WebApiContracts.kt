package org.ktcs.kernel.web.contract

import org.ktcs.kernel.web.contract.OpenApiContract.Violation
import java.net.URI

/**
 * The two contracts every web API response in the kernel tests must keep: kTCS's own OpenAPI document (each status
 * kTCS answers must be described there, each body must match) and openTCS's v1 specification, wherever openTCS
 * describes the operation and status (kTCS-only routes such as `/ws` and `/openapi.yaml` have only kTCS's), except
 * for the [OpenTcsSpecDefects].
 */
object WebApiContracts {
    private const val OPEN_TCS_FOLDER = "fixtures/opentcs/web-api/opentcs-7.5-head/service-web-api-v1"
    val openTcs = OpenApiContract("openTCS v1", "$OPEN_TCS_FOLDER/openapi.yaml")
    val ktcs = OpenApiContract("kTCS", "org/ktcs/kernel/web/openapi.yaml")

    /** The violations of a response to [method] [url] (a URL under `/v1`, or its path). */
    fun violations(method: String, url: String, status: Int, contentType: String?, body: String): List<Violation> {
        val path = URI(url).path.substringAfter("/v1", missingDelimiterValue = "")
        require(path.isNotEmpty() || URI(url).path == "/v1") { "$url is not under /v1" }
        val own = ktcs.template(method, path)
            ?: return if (status == 404) {
                // No such route: the 404 is right, and its body is still kTCS's error array.
                ktcs.violationsOf(pointer = "/components/schemas/Errors", json = body, where = "kTCS: 404 for $path")
            } else {
                listOf(Violation("kTCS: $method $path", null, "is not in kTCS's document, yet answered $status"))
            }
        val theirs = openTcs.template(method, path)?.takeIf { openTcs.describes(method, it, status) }
        val openTcsViolations =
            theirs?.let { openTcs.violations(method, it, status, contentType, KtcsFields.strip(body)) }.orEmpty()
        return ktcs.violations(method, own, status, contentType, body) +
            OpenTcsSpecDefects.unexcused(openTcsViolations)
    }

    /** The violations of [json] against openTCS's schema at [pointer] of [file] (a path under the spec's folder). */
    fun openTcsSchemaViolations(file: String, pointer: String, json: String): List<Violation> =
        OpenTcsSpecDefects.unexcused(openTcs.violationsOf("$OPEN_TCS_FOLDER/$file", pointer, KtcsFields.strip(json)))

    /** Fails the test with every violation of the response, naming operation, JSON pointer and message. */
    fun check(method: String, url: String, status: Int, contentType: String?, body: String) {
        val found = violations(method, url, status, contentType, body)
        if (found.isNotEmpty()) {
            throw AssertionError("the response breaks the web API contract:\n" + found.joinToString("\n"))
        }
    }
}
