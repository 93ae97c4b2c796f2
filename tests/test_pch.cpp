// SPDX-License-Identifier: Apache-2.0
// The owner of the test programs' shared precompiled header (tests/CMakeLists.txt): a
// program compiled like them that does nothing.
int main()
{
    return 0;
}
