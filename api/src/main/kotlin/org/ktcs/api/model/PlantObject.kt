package org.ktcs.api.model

/**
 * Anything in the plant model. Names are unique across all kinds of objects, as in openTCS.
 */
public sealed interface PlantObject {
    /** The object's unique name. */
    public val name: String

    /** Free-form properties; keys starting with `tcs:` are reserved for kTCS and openTCS. */
    public val properties: Map<String, String>
}
