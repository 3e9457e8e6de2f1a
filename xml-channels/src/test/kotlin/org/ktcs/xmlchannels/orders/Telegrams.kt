package org.ktcs.xmlchannels.orders

import org.ktcs.xmlchannels.XmlTree

// Telegrams and receipts for the order channel tests.

const val XSI = "http://www.w3.org/2001/XMLSchema-instance"

fun orderSet(vararg orders: String) = "<tcsOrderSet>${orders.joinToString("")}</tcsOrderSet>"

fun transport(id: String, location: String = "Storage 01", attributes: String = "", body: String = "") =
    """<order xsi:type="transport" id="$id" $attributes xmlns:xsi="$XSI">""" +
        """<destination locationName="$location" operation="Load cargo"/>$body</order>"""

fun String.responses() = XmlTree.of(this).children

fun response(id: String, orderName: String) = XmlTree(
    "response",
    sortedMapOf(
        "xsi:type" to "transportResponse",
        "executionSuccessful" to "true",
        "orderName" to orderName,
        "id" to id,
    ),
    emptyList(),
)

fun failure(id: String, reason: String) = XmlTree(
    "response",
    sortedMapOf(
        "xsi:type" to "transportResponse",
        "executionSuccessful" to "false",
        "orderName" to "",
        "id" to id,
        "reason" to reason,
    ),
    emptyList(),
)
