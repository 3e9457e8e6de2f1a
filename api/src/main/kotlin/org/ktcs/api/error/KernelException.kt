package org.ktcs.api.error

/**
 * A request the kernel refuses. The message names the object and the problem, ready to show to a user. The web API
 * maps [InvalidRequestException] to 400, [ObjectUnknownException] to 404, and [ObjectExistsException] and
 * [IllegalStateChangeException] to 409.
 */
public sealed class KernelException(message: String) : RuntimeException(message)

/** The request itself is wrong: a bad value, a missing field, an operation a location does not allow. */
public class InvalidRequestException(message: String) : KernelException(message)

/** The request names an object that does not exist. */
public class ObjectUnknownException(message: String) : KernelException(message)

/** An object with the requested name exists already. */
public class ObjectExistsException(message: String) : KernelException(message)

/** The object is not in a state that allows the request, e.g. withdrawing a finished order. */
public class IllegalStateChangeException(message: String) : KernelException(message)
