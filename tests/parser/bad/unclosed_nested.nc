If [1]
  While [1]
