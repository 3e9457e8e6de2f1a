package org.ktcs.api.model

/**
 * How the plant is drawn.
 *
 * @property scaleX millimetres per pixel along x.
 * @property scaleY millimetres per pixel along y.
 */
public data class VisualLayout(
    val name: String = "VLayout",
    val scaleX: Double = 50.0,
    val scaleY: Double = 50.0,
    val layers: List<Layer> = listOf(Layer(0, 0, true, "Default layer", 0)),
    val layerGroups: List<LayerGroup> = listOf(LayerGroup(0, "Default layer group", true)),
    val properties: Map<String, String> = emptyMap(),
)

/** A drawing layer; elements refer to it by [id]. Layers are drawn in [ordinal] order. */
public data class Layer(val id: Int, val ordinal: Int, val visible: Boolean, val name: String, val groupId: Int)

/** A group of layers that can be shown or hidden together. */
public data class LayerGroup(val id: Int, val name: String, val visible: Boolean)
