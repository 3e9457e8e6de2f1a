package org.ktcs.kernel.web.docs

import io.ktor.server.routing.HttpMethodRouteSelector
import io.ktor.server.routing.PathSegmentConstantRouteSelector
import io.ktor.server.routing.PathSegmentParameterRouteSelector
import io.ktor.server.routing.PathSegmentTailcardRouteSelector
import io.ktor.server.routing.RoutingNode
import io.ktor.server.routing.getAllRoutes

/** One operation: an HTTP method and a path template in OpenAPI's spelling (`/v1/vehicles/{NAME}`). */
data class Operation(val method: String, val path: String) {
    override fun toString() = "$method $path"
}

/** The operations a Ktor routing tree answers: every node with handlers, with the method and path leading to it. */
fun RoutingNode.operations(): Set<Operation> = getAllRoutes().mapNotNull(::operationOf).toSet()

private fun operationOf(node: RoutingNode): Operation? {
    val chain = generateSequence(node) { it.parent }.toList().reversed()
    val method = chain.firstNotNullOfOrNull { (it.selector as? HttpMethodRouteSelector)?.method?.value } ?: return null
    val path = chain.mapNotNull { segmentOf(it) }.joinToString("") { "/$it" }
    return Operation(method, path.ifEmpty { "/" })
}

// Other selectors (trailing slash, the WebSocket's Upgrade header, the root) add no path segment.
private fun segmentOf(node: RoutingNode): String? = when (val selector = node.selector) {
    is PathSegmentConstantRouteSelector -> selector.value
    is PathSegmentParameterRouteSelector -> "{${selector.name}}"
    is PathSegmentTailcardRouteSelector -> "{...}"
    else -> null
}
