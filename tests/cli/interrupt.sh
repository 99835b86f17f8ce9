#!/bin/sh
# A run stopped by a signal: it ends within a few seconds with exit 3, and every report
# says what was finished, the property that was running incomplete ("interrupted").
# Usage: interrupt.sh TIOA_CHECK SIGNAL WORKDIR ARGS...
tool=$1 signal=$2 dir=$3
shift 3
cd "$dir" || exit 1
name=interrupted_$signal
rm -f $name.json $name.xml
"$tool" "$@" --json --junit $name.xml > $name.json &
pid=$!
sleep 1
started=$(date +%s)
kill -"$signal" "$pid"
wait "$pid"
code=$?
took=$(( $(date +%s) - started ))
[ "$code" -eq 3 ] || { echo "exit $code, expected 3"; exit 1; }
[ "$took" -le 5 ] || { echo "took ${took} s after the signal"; exit 1; }
grep -q '"interrupted": true' $name.json || { echo "no \"interrupted\" in the JSON"; exit 1; }
grep -q 'interrupted' $name.xml || { echo "the JUnit file does not say interrupted"; exit 1; }
echo "stopped ${took} s after SIG${signal}, exit 3"
