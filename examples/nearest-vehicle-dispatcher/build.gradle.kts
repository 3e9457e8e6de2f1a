plugins {
    id("ktcs.kotlin-jvm")
}

dependencies {
    implementation(project(":kernel"))
    testImplementation(project(":adapters-loopback"))
}
