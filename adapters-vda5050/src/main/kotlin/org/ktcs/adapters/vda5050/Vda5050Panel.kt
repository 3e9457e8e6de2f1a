package org.ktcs.adapters.vda5050

import org.ktcs.api.driver.DriverCommand
import org.ktcs.api.driver.DriverPanel
import org.ktcs.api.driver.DriverParameter
import org.ktcs.api.driver.ParameterType

/** A VDA 5050 vehicle's panel in the overview: connection, state age, errors, factsheet, and the instant actions. */
internal object Vda5050Panel {
    val panel: DriverPanel = DriverPanel(
        title = "VDA 5050 (MQTT)",
        resourceDirectory = "org/ktcs/adapters/vda5050/panel",
        classLoader = Vda5050Panel::class.java.classLoader,
        commands = listOf(
            DriverCommand(
                Vda5050Driver.INIT_POSITION,
                "Sends initPosition: tells the vehicle it stands on a point",
                listOf(DriverParameter("point", ParameterType.POINT, "the point")),
            ),
            DriverCommand(Vda5050Driver.STATE_REQUEST, "Sends stateRequest: asks the vehicle for a state message"),
            DriverCommand(
                Vda5050Driver.FACTSHEET_REQUEST,
                "Sends factsheetRequest: asks the vehicle for its factsheet",
            ),
            DriverCommand(Vda5050Driver.START_PAUSE, "Sends startPause: the vehicle stops where it is"),
            DriverCommand(Vda5050Driver.STOP_PAUSE, "Sends stopPause: the vehicle goes on"),
        ),
    )
}
