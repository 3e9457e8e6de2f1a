package org.ktcs.adapters.vda5050.bench

/** What `ktcs vda5050-bench` runs. */
data class Vda5050BenchOptions(
    val vehicles: Int = 100,
    val orders: Int = 200,
    /** The grid's side; by default as dense as 100 vehicles on 40x40, on which 100 loopback vehicles finish. */
    val grid: Int? = null,
    val timeFactor: Double = 4.0,
    val timeoutSeconds: Long = 900,
    /** Only the broker's steps ([BrokerSteps]), this many rounds of each, no kTCS run. */
    val brokerStepRounds: Int = 0,
) {
    companion object {
        const val USAGE = """usage: ktcs vda5050-bench [--vehicles N] [--orders M] [--grid G] [--time-factor F] [--timeout S] [--broker-steps R]
  Starts ./ktcs twice on a generated GxG traffic grid (default: as dense as 100 vehicles on 40x40) with N vehicles and posts the same M orders: once with VDA 5050
  vehicles played by the simulator over the embedded broker (state 1 Hz, visualization 10 Hz), once with loopback
  vehicles. Prints the orders finished, kTCS's CPU seconds per finished order in both runs and their ratio (with and
  without the embedded broker's threads, which run in kTCS's process), kTCS's CPU by thread group, the
  broker round trip (publish to receive, QoS 0) p50/p99 measured every 100 ms during the VDA 5050 run, and the
  floor: the builtin embedded broker alone (in the bench's process) receiving the N simulated vehicles' messages with no
  subscriber for 20 s, its CPU per second and per finished order at the VDA 5050 run's order rate.
  --broker-steps R runs only, R times alternately, HiveMQ receiving the N vehicles' messages alone and
  with a do-nothing publish inbound interceptor, and the builtin broker alone, and prints per message the CPU and
  the context switches of the broker's (and HiveMQ's extension executor's) threads."""

        fun parse(args: List<String>): Vda5050BenchOptions {
            var options = Vda5050BenchOptions()
            var i = 0
            fun number(): Long = args.getOrNull(++i)?.toLongOrNull()?.takeIf { it > 0 }
                ?: throw IllegalArgumentException("${args[i - 1]} needs a positive whole number")
            while (i < args.size) {
                options = when (val arg = args[i]) {
                    "--vehicles" -> options.copy(vehicles = number().toInt())

                    "--orders" -> options.copy(orders = number().toInt())

                    "--grid" -> options.copy(grid = number().toInt())

                    "--timeout" -> options.copy(timeoutSeconds = number())

                    "--broker-steps" -> options.copy(brokerStepRounds = number().toInt())

                    "--time-factor" -> options.copy(
                        timeFactor = args.getOrNull(++i)?.toDoubleOrNull()?.takeIf { it > 0 }
                            ?: throw IllegalArgumentException("--time-factor needs a positive number"),
                    )

                    else -> throw IllegalArgumentException("unknown option '$arg'")
                }
                i++
            }
            return options
        }
    }
}
